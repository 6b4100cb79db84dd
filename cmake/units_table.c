/* SPDX-License-Identifier: MIT */
/* Writes the C source of cs_units_usual_table (src/io/load/units_udunits.c): the usual units
 * (cs_units_usual) with their factors as udunits2's database converts them (cs_units_write_table), so
 * that a run whose model names only these never reads the database. Run by the build:
 * units_table OUT.c */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>

#include "load/units.h"

const char cs_units_usual_table[] = ""; /* here every unit is the database's */

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: units_table OUT.c\n");
        return 2;
    }
    char *table = NULL;
    size_t size = 0;
    cs_error err;
    cs_units *u = cs_units_open(&err);
    FILE *mem = open_memstream(&table, &size);
    if (!u || !mem) {
        fprintf(stderr, "units_table: %s\n", u ? "out of memory" : err.message);
        return 1;
    }
    int written = cs_units_write_table(u, cs_units_usual, cs_units_usual_count, 0, mem);
    fclose(mem);
    cs_units_free(u);
    if (written < 0) {
        fprintf(stderr, "units_table: out of memory\n");
        return 1;
    }
    FILE *out = fopen(argv[1], "w");
    if (!out) {
        perror(argv[1]);
        return 1;
    }
    fprintf(out, "/* Written by cmake/units_table.c from udunits2's database: %d units. */\n", written);
    fprintf(out, "const char cs_units_usual_table[] =\n    \"");
    for (const char *c = table; *c; c++)
        fputs(*c == '\t' ? "\\t" : *c == '\n' ? (c[1] ? "\\n\"\n    \"" : "\\n") : (char[]){*c, '\0'}, out);
    fputs("\";\n", out);
    free(table);
    return fclose(out) == 0 ? 0 : 1;
}
