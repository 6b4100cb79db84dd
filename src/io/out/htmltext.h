/* SPDX-License-Identifier: MIT */
/* Text that came from a user (a model's name, a spec's paths and values, a run folder's name) into an
 * output, made safe for what reads it: an HTML page (html.h), a Markdown file, a CSV cell a spreadsheet
 * opens, a terminal. Apart from html.h's figures so that the designer page's WebAssembly, which has no
 * cairo, writes it too. */
#ifndef CS_HTMLTEXT_H
#define CS_HTMLTEXT_H

#include <stdio.h>

/* s with &, <, > and " escaped (NULL: nothing). */
void cs_html_text(FILE *f, const char *s);
/* s as a Markdown code span: `s`, or <code>s escaped</code> where s holds a backtick, <, > or &. */
void cs_md_code(FILE *f, const char *s);
/* s as a CSV cell: a text that a spreadsheet would take for a formula (it begins with =, +, -, @, a tab
 * or a carriage return; a number is left alone) or that begins with ' gets a leading '; quoted where it
 * holds a comma, a quote or a line break, or always with quote. */
void cs_csv_text(FILE *f, const char *s, int quote);
/* The text of a cell cs_csv_text wrote (its field as read, unquoted), in place: the leading ' it added
 * taken off. */
void cs_csv_untext(char *cell);
/* s on a terminal: control characters (escape sequences, carriage returns, line breaks) as '?'. */
void cs_term_text(FILE *f, const char *s);

#endif
