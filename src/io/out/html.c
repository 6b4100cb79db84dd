/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include "out/html.h"

#include <stdlib.h>
#include <string.h>

#include "status.h"

cs_status cs_html_figure(FILE *f, const char *id, double width, double height, cs_plot_draw_fn draw,
                         const void *user, cs_error *err) {
    char *svg = NULL;
    size_t size = 0;
    FILE *mem = open_memstream(&svg, &size);
    if (!mem) return cs_status_set(err, CS_ERR_MEMORY, "out of memory for a page's figure");
    cs_status rc = cs_plot_write(mem, CS_PLOT_SVG, width, height, draw, user, err);
    fclose(mem);
    const char *p = svg ? strstr(svg, "<svg") : NULL; /* without the XML declaration */
    if (rc == CS_OK && !p) rc = cs_status_set(err, CS_ERR_IO, "a figure without <svg>");
    /* every reference to an id is id="X", href="#X" or url(#X): each X becomes <id>-X */
    static const char *const refs[] = {"id=\"", "href=\"#", "url(#"};
    while (rc == CS_OK && *p) {
        const char *next = NULL;
        size_t len = 0;
        for (int k = 0; k < 3; k++) {
            const char *q = strstr(p, refs[k]);
            if (q && (!next || q < next)) next = q, len = strlen(refs[k]);
        }
        if (!next) {
            fputs(p, f);
            break;
        }
        fwrite(p, 1, (size_t)(next - p) + len, f);
        fprintf(f, "%s-", id);
        p = next + len;
    }
    free(svg);
    return rc;
}
