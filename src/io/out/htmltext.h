/* Text into an HTML page (html.h): what a page takes from a model, a spec or the command line, escaped.
 * Apart from html.h's figures so that the designer page's WebAssembly, which has no cairo, writes it too. */
#ifndef CS_HTMLTEXT_H
#define CS_HTMLTEXT_H

#include <stdio.h>

/* s with &, <, > and " escaped (NULL: nothing). */
void cs_html_text(FILE *f, const char *s);

#endif
