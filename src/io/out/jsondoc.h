/* SPDX-License-Identifier: MIT */
/* The JSON documents the writers make (summary.json, a sweep's summary and journal, the pages' data),
 * built with json-c's object API and written by it: structure and string escaping are json-c's, numbers
 * carry cs_g10's exact "%.10g" text, and a document's few line breaks (one event per line) are members
 * wrapped to be written with a line break after or before them. */
#ifndef CS_JSONDOC_H
#define CS_JSONDOC_H

#include <json-c/json.h>
#include <stdio.h>

/* v as a JSON number written as cs_g10 writes it (the text kept with the value); NULL, JSON's null, if v
 * is not finite. */
json_object *cs_jnum(double v);
/* n numbers as a JSON array, each written to digits significant digits ("%.*g", 0 for -0), a NaN as null
 * where nan_null (else as printf writes it: the caller keeps them finite). One object for the list, the
 * numbers kept as a copy and written by its serializer: for writing only (json-c sees an empty array).
 * NULL if out of memory. */
json_object *cs_jnums(const double *v, int n, int digits, int nan_null);
/* s as a JSON string; NULL (null) for NULL. */
json_object *cs_jstr(const char *s);
/* A member's value written as v's text then a line break (after), or a line break then v's text: for
 * writing only (its type is no JSON type of v's). Takes v (may be NULL: null); NULL if out of memory. */
json_object *cs_jline_after(json_object *v);
json_object *cs_jline_before(json_object *v);
/* obj written with the members named in keys (NULL-ended, kept by the caller) each on a new line: a line
 * break after the comma before it (each member's text, key and value, is json-c's). */
void cs_jkeys_on_new_line(json_object *obj, const char *const *keys);
/* A line break after the last member of obj so far (its value wrapped by cs_jline_after); 0, or -1 if
 * out of memory (obj has no member: nothing done, 0). */
int cs_jline_after_last(json_object *obj);
/* doc's text, compact (no spaces, '/' not escaped); for a page (page nonzero) also <, > and & as \u003c,
 * \u003e and \u0026, so that it may stand inside an HTML script element. Written to f followed by end
 * (may be ""). Returns 0, or -1 if out of memory. doc is not freed. */
int cs_json_write(FILE *f, json_object *doc, int page, const char *end);
/* doc's text as cs_json_write writes it (not for a page), a copy to free; NULL if out of memory. */
char *cs_json_text(json_object *doc);

#endif
