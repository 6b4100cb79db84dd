/* SPDX-License-Identifier: MIT */
/* `cablesim sweep SPEC [-o DIR] [--threads N] ...`: a study over a model's values (app/sweep.c). */
#ifndef CS_SWEEPCMD_H
#define CS_SWEEPCMD_H

/* argv[1] is "sweep". Returns the exit status: 0 done, 1 the outputs failed, 2 a bad spec or usage. */
int cs_sweep_command(int argc, char **argv);
/* `cablesim check FILE ...` where FILE is a sweep spec (a mapping with `vary`)? */
int cs_sweep_check_wanted(int argc, char **argv);
/* Check the spec and its model with run 0's inputs and each grid level: 0 valid, 2 problems printed. */
int cs_sweep_check_command(int argc, char **argv);

#endif
