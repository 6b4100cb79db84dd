/* SPDX-License-Identifier: MIT */
/* The measured and published values `cablesim validate` compares its runs with, read from the CSV files
 * of data/validation/ (beside the parts library, found the same way: the loader's data folder). Each
 * file names its source in its '#' comment lines, then its columns in a header line, then a row a line.
 * Every problem is "file:line:column: what is wrong (what was expected)". */
#ifndef CS_VALIDATION_H
#define CS_VALIDATION_H

#include <stddef.h>

#include "cablesim/sim.h"

enum { CS_BOGIE_TESTS = 10, CS_EQ21_MAX = 16 };

/* One crash test's response parameters: as measured, or as a simulation gave them. */
typedef struct cs_crash_values {
    double decel_g;  /* max 50-ms average deceleration, g (its magnitude) */
    double exit_mph; /* exit speed */
    double brk[2];   /* when cable 1 and cable 2 broke, s */
} cs_crash_values;

/* A bogie test of a post in soil. */
typedef struct cs_bogie_test {
    char name[16];
    double mph, embedment_mm, deflection_mm, energy_ftlb;
    int pullout; /* 1: pulled out of the ground; 0: rotated in the soil */
} cs_bogie_test;

/* The bogie tests' rig: the post's section (a library part) and its flange, the bogie and the soil. */
typedef struct cs_bogie_rig {
    char section[32];
    double flange_in, mass_lb, head_height_in, head_diameter_in, soil_psf;
} cs_bogie_rig;

/* A footing's capacity by Eq. 21 as the paper gives it, with the soil and load height it takes. */
typedef struct cs_eq21_point {
    double width_ft, depth_ft, p_lb, s1_psf, h_ft;
} cs_eq21_point;

typedef struct cs_validation_data {
    cs_crash_values aps1_test, aps1_paper; /* aps1-crash-test.csv */
    cs_bogie_test bogie[CS_BOGIE_TESTS];   /* post-bogie-tests.csv: the paper's ten, in its order */
    cs_bogie_rig rig;                      /* bogie-rig.csv */
    cs_eq21_point eq21[CS_EQ21_MAX];       /* eq21-table4.csv */
    int eq21_count;
} cs_validation_data;

/* Read the files of dir (data/validation). CS_OK, or with err filled ("file:line:column: what and why")
 * CS_ERR_IO (a file that cannot be opened), CS_ERR_INVALID (a value or row the file must not have) or
 * CS_ERR_MEMORY. */
cs_status cs_validation_read(const char *dir, cs_validation_data *out, cs_error *err);

#endif
