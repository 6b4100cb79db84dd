/* SPDX-License-Identifier: MIT */
/* The CSV reader (load/csvread.h): quoted commas, quoted line breaks and doubled quotes; the ' before a
 * formula-like text undone only when asked; comment and blank lines skipped only when asked; a cell
 * limit as a problem or as the rest of the row; a line too long; each cell's line and column, and a
 * problem's; a quote only around a cell. */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "load/csvread.h"

/* The next row of r: its cells' texts (NULL-terminated) at the given lines and columns. */
static void expect_row(cs_csv *r, const char *const *text, const long *line, const int *col) {
    int rc = cs_csv_next(r);
    if (rc != 1) fail_msg("no row (%d): %s", rc, r->why);
    int n = 0;
    while (text[n])
        n++;
    assert_int_equal(r->count, n);
    for (int k = 0; k < n; k++) {
        if (strcmp(r->cell[k], text[k]) != 0) fail_msg("cell %d: '%s', want '%s'", k, r->cell[k], text[k]);
        if (r->cell_line[k] != line[k] || r->cell_col[k] != col[k])
            fail_msg("cell %d at %ld:%d, want %ld:%d", k, r->cell_line[k], r->cell_col[k], line[k], col[k]);
    }
    assert_int_equal(r->line, line[0]);
}

/* RFC 4180: a comma, a doubled quote and a line break inside quotes are the cell's; the row goes on from
 * the line the quote ends on; a CR LF's CR is not a cell's, one inside quotes is. */
static void quoted_cells(void **state) {
    (void)state;
    cs_csv r;
    cs_csv_open_text(&r, "a,\"b,c\",\"say \"\"hi\"\"\"\r\n\"two\nlines\",x\r\n\"cr\r\n\",\"\"\n",
                     CS_CSV_QUOTED, 8);
    expect_row(&r, (const char *[]){"a", "b,c", "say \"hi\"", NULL}, (long[]){1, 1, 1}, (int[]){1, 3, 9});
    expect_row(&r, (const char *[]){"two\nlines", "x", NULL}, (long[]){2, 3}, (int[]){1, 8});
    expect_row(&r, (const char *[]){"cr\r\n", "", NULL}, (long[]){4, 5}, (int[]){1, 3});
    assert_int_equal(cs_csv_next(&r), 0);
    cs_csv_close(&r);
    /* without CS_CSV_QUOTED a quote is a character like any other */
    cs_csv_open_text(&r, "\"b,c\"\n", 0, 8);
    expect_row(&r, (const char *[]){"\"b", "c\"", NULL}, (long[]){1, 1}, (int[]){1, 4});
    cs_csv_close(&r);
}

/* The ' a writer puts before =, +, -, @, tab or CR text is undone when asked, a number's kept: "'-1" is
 * the text -1 only if -1 is not a number, which it is. */
static void untext(void **state) {
    (void)state;
    const char *csv = "'=SUM(A1),'-1,'@x,\"'-a,b\",'plain\n";
    cs_csv r;
    cs_csv_open_text(&r, csv, CS_CSV_QUOTED | CS_CSV_UNTEXT, 8);
    expect_row(&r, (const char *[]){"=SUM(A1)", "'-1", "@x", "-a,b", "'plain", NULL}, (long[]){1, 1, 1, 1, 1},
               (int[]){1, 11, 15, 19, 27});
    cs_csv_close(&r);
    cs_csv_open_text(&r, csv, CS_CSV_QUOTED, 8);
    expect_row(&r, (const char *[]){"'=SUM(A1)", "'-1", "'@x", "'-a,b", "'plain", NULL},
               (long[]){1, 1, 1, 1, 1}, (int[]){1, 11, 15, 19, 27});
    cs_csv_close(&r);
}

/* '#' lines and empty lines (a lone CR too) skipped when asked, counted in the lines all the same; read as
 * rows when not asked; a CR as the end of a line's text when asked. */
static void comments_and_blanks(void **state) {
    (void)state;
    const char *csv = "# source\nh1,h2\n\n\r\n# more\n1,2\n";
    cs_csv r;
    cs_csv_open_text(&r, csv, CS_CSV_COMMENTS | CS_CSV_BLANKS, 4);
    expect_row(&r, (const char *[]){"h1", "h2", NULL}, (long[]){2, 2}, (int[]){1, 4});
    expect_row(&r, (const char *[]){"1", "2", NULL}, (long[]){6, 6}, (int[]){1, 3});
    assert_int_equal(cs_csv_next(&r), 0);
    cs_csv_close(&r);
    cs_csv_open_text(&r, csv, 0, 4);
    expect_row(&r, (const char *[]){"# source", NULL}, (long[]){1}, (int[]){1});
    expect_row(&r, (const char *[]){"h1", "h2", NULL}, (long[]){2, 2}, (int[]){1, 4});
    expect_row(&r, (const char *[]){"", NULL}, (long[]){3}, (int[]){1});
    expect_row(&r, (const char *[]){"", NULL}, (long[]){4}, (int[]){1});
    cs_csv_close(&r);
    /* with CS_CSV_CR_ENDS a line's text ends at its first CR: a line that begins with one is blank */
    cs_csv_open_text(&r, "a,b\rc,d\n\rx\n1,2\n", CS_CSV_BLANKS | CS_CSV_CR_ENDS, 4);
    expect_row(&r, (const char *[]){"a", "b", NULL}, (long[]){1, 1}, (int[]){1, 3});
    expect_row(&r, (const char *[]){"1", "2", NULL}, (long[]){3, 3}, (int[]){1, 3});
    assert_int_equal(cs_csv_next(&r), 0);
    cs_csv_close(&r);
}

/* A line over max_line characters is a problem at its line, column 1, a comment line's too; one of
 * max_line is not, the last line's without its '\n' either. */
static void line_too_long(void **state) {
    (void)state;
    char csv[64];
    snprintf(csv, sizeof csv, "#%s\n%s\n%s", "123456789", "a,b,c,d,e", "a,b,c,d,efg");
    cs_csv r;
    cs_csv_open_text(&r, csv, CS_CSV_COMMENTS, 8);
    r.max_line = 10;
    expect_row(&r, (const char *[]){"a", "b", "c", "d", "e", NULL}, (long[]){2, 2, 2, 2, 2},
               (int[]){1, 3, 5, 7, 9});
    assert_int_equal(cs_csv_next(&r), -1);
    assert_string_equal(r.why, "a line of more than 10 characters (expected shorter lines)");
    assert_int_equal(r.why_line, 3);
    assert_int_equal(r.why_col, 1);
    cs_csv_close(&r);
    cs_csv_open_text(&r, "#12345678901\n", CS_CSV_COMMENTS, 8);
    r.max_line = 10;
    assert_int_equal(cs_csv_next(&r), -1);
    assert_int_equal(r.why_line, 1);
    cs_csv_close(&r);
}

/* Past max_cells: a problem at the first cell too many, or, with CS_CSV_REST, the last cell the rest. */
static void too_many_cells(void **state) {
    (void)state;
    cs_csv r;
    cs_csv_open_text(&r, "1,2\n1,22,333,4\n", 0, 3);
    expect_row(&r, (const char *[]){"1", "2", NULL}, (long[]){1, 1}, (int[]){1, 3});
    assert_int_equal(cs_csv_next(&r), -1);
    assert_string_equal(r.why, "more than 3 values");
    assert_int_equal(r.why_line, 2);
    assert_int_equal(r.why_col, 10);
    cs_csv_close(&r);
    cs_csv_open_text(&r, "1,22,333,4\n", CS_CSV_REST, 3);
    expect_row(&r, (const char *[]){"1", "22", "333,4", NULL}, (long[]){1, 1, 1}, (int[]){1, 3, 6});
    cs_csv_close(&r);
}

/* A quote opens a cell only as its first character: further in (1"2, a space before it) it is the cell's
 * own; after a closing quote only a comma or the line's end (its CR LF's CR too) may come, else a problem
 * at that character ("12"5 is not read as 125). */
static void quote_only_around_a_cell(void **state) {
    (void)state;
    cs_csv r;
    cs_csv_open_text(&r, "1\"2, \"3\",\"4\"\r\n\"12\"5,6\n", CS_CSV_QUOTED, 4);
    expect_row(&r, (const char *[]){"1\"2", " \"3\"", "4", NULL}, (long[]){1, 1, 1}, (int[]){1, 5, 10});
    assert_int_equal(cs_csv_next(&r), -1);
    assert_string_equal(r.why, "'5' after a quoted cell's closing quote (expected a comma or the end of the "
                               "line; a quote inside a quoted cell is doubled: \"\")");
    assert_int_equal(r.why_line, 2);
    assert_int_equal(r.why_col, 5);
    cs_csv_close(&r);
}

/* A quote not closed by the end is a problem where it opens; a file read as its text is. */
static void unclosed_quote_in_a_file(void **state) {
    (void)state;
    FILE *f = tmpfile();
    assert_non_null(f);
    fputs("a,b\nc,\"d\ne,f\n", f);
    rewind(f);
    cs_csv r;
    cs_csv_open_file(&r, f, CS_CSV_QUOTED, 4);
    expect_row(&r, (const char *[]){"a", "b", NULL}, (long[]){1, 1}, (int[]){1, 3});
    assert_int_equal(cs_csv_next(&r), -1);
    assert_string_equal(r.why, "a quoted cell not closed (expected a closing \" before the end of the file)");
    assert_int_equal(r.why_line, 2);
    assert_int_equal(r.why_col, 3);
    cs_csv_close(&r);
    fclose(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(quoted_cells),
                                       cmocka_unit_test(untext),
                                       cmocka_unit_test(comments_and_blanks),
                                       cmocka_unit_test(line_too_long),
                                       cmocka_unit_test(too_many_cells),
                                       cmocka_unit_test(unclosed_quote_in_a_file),
                                       cmocka_unit_test(quote_only_around_a_cell)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
