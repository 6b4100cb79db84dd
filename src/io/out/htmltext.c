/* SPDX-License-Identifier: MIT */
#include "out/htmltext.h"

#include <stdlib.h>
#include <string.h>

void cs_html_text(FILE *f, const char *s) {
    for (; s && *s; s++) {
        if (*s == '&')
            fputs("&amp;", f);
        else if (*s == '<')
            fputs("&lt;", f);
        else if (*s == '>')
            fputs("&gt;", f);
        else if (*s == '"')
            fputs("&quot;", f);
        else
            fputc(*s, f);
    }
}

void cs_md_code(FILE *f, const char *s) {
    if (!strpbrk(s, "`<>&")) {
        fprintf(f, "`%s`", s);
        return;
    }
    fputs("<code>", f);
    cs_html_text(f, s);
    fputs("</code>", f);
}

/* Whether a spreadsheet would take the cell s for a formula: it begins with =, +, -, @, a tab or a
 * carriage return and is not a number. */
static int formula_like(const char *s) {
    if (!s[0] || !strchr("=+-@\t\r", s[0])) return 0;
    char *end;
    strtod(s, &end);
    return end == s || *end != '\0';
}

void cs_csv_text(FILE *f, const char *s, int quote) {
    int mark = formula_like(s) || (s[0] == '\'' && (formula_like(s + 1) || s[1] == '\''));
    quote = quote || strpbrk(s, ",\"\n\r") != NULL;
    if (quote) fputc('"', f);
    if (mark) fputc('\'', f);
    for (; *s; s++) {
        if (quote && *s == '"') fputc('"', f);
        fputc(*s, f);
    }
    if (quote) fputc('"', f);
}

void cs_csv_untext(char *cell) {
    if (cell[0] == '\'' &&
        (formula_like(cell + 1) || (cell[1] == '\'' && (formula_like(cell + 2) || cell[2] == '\''))))
        memmove(cell, cell + 1, strlen(cell));
}

void cs_term_text(FILE *f, const char *s) {
    for (; s && *s; s++)
        fputc((unsigned char)*s < 0x20 || *s == 0x7f ? '?' : *s, f);
}
