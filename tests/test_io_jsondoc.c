/* SPDX-License-Identifier: MIT */
/* The JSON documents' writer (out/jsondoc.h): numbers keep cs_g10's "%.10g" text to the byte and read
 * back within its 10 digits, strings are escaped by json-c ('/' left as it is), the line-break wrappers
 * put a line break after or before a member, or before a named key, and leave the document valid JSON
 * that reads back the same, a list of numbers keeps the digits asked for and reads back within them, and a
 * page's text has no <, > or & left. */
#include <json-c/json.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "out/jsondoc.h"

/* doc's text as cs_json_write writes it (page or not), to free. */
static char *text_of(json_object *doc, int page) {
    char *buf = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&buf, &size);
    assert_non_null(f);
    assert_int_equal(cs_json_write(f, doc, page, "\n"), 0);
    fclose(f);
    return buf;
}

static void numbers_keep_their_text(void **state) {
    (void)state;
    const double v[] = {0.1 + 0.2, 1e-5, -0.0, 1e10, 123456789012.0, 6.511686653, -9.544411091e-05, 0.0};
    const char *const want = "[0.3,1e-05,-0,1e+10,1.23456789e+11,6.511686653,-9.544411091e-05,0,null]\n";
    json_object *a = json_object_new_array();
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        json_object_array_add(a, cs_jnum(v[i]));
    json_object_array_add(a, cs_jnum(NAN)); /* not finite: null */
    char *text = text_of(a, 0);
    assert_string_equal(text, want);
    json_object *back = json_tokener_parse(text);
    assert_non_null(back);
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) /* 10 significant digits: 5e-10 relative */
        CHECK_ABS(json_object_get_double(json_object_array_get_idx(back, i)), v[i], 5e-10 * fabs(v[i]));
    assert_null(json_object_array_get_idx(back, 8));
    json_object_put(back), json_object_put(a);
    free(text);
}

static void number_lists_to_their_digits(void **state) {
    (void)state;
    const double v[] = {1.0 / 3.0, -0.0, 2.5e-7, 123456789.0, NAN, 4.0};
    json_object *o = json_object_new_object();
    json_object_object_add(o, "six", cs_jnums(v, 6, 6, 1));
    json_object_object_add(o, "all", cs_jnums(v, 2, 17, 0));
    json_object_object_add(o, "none", cs_jnums(v, 0, 6, 0));
    char *text = text_of(o, 0);
    assert_string_equal(text, "{\"six\":[0.333333,0,2.5e-07,1.23457e+08,null,4],"
                              "\"all\":[0.33333333333333331,0],\"none\":[]}\n");
    json_object *back = json_tokener_parse(text), *six, *all;
    assert_non_null(back);
    assert_true(json_object_object_get_ex(back, "six", &six));
    assert_true(json_object_object_get_ex(back, "all", &all));
    assert_int_equal(json_object_array_length(six), 6);
    for (int i = 0; i < 6; i++) /* 6 significant digits: 5e-6 relative */
        if (i != 4)
            CHECK_ABS(json_object_get_double(json_object_array_get_idx(six, i)), v[i], 5e-6 * fabs(v[i]));
    assert_null(json_object_array_get_idx(six, 4));
    /* 17 digits: the double itself */
    CHECK_ABS(json_object_get_double(json_object_array_get_idx(all, 0)), v[0], 0.0);
    json_object_put(back), json_object_put(o);
    free(text);
}

static void strings_escaped_by_json_c(void **state) {
    (void)state;
    json_object *o = json_object_new_object();
    json_object_object_add(o, "path", cs_jstr("a/b \"c\" \\d\n\x01 <e&f>"));
    json_object_object_add(o, "none", cs_jstr(NULL));
    char *text = text_of(o, 0), *page = text_of(o, 1);
    assert_string_equal(text, "{\"path\":\"a/b \\\"c\\\" \\\\d\\n\\u0001 <e&f>\",\"none\":null}\n");
    assert_string_equal(
        page, "{\"path\":\"a/b \\\"c\\\" \\\\d\\n\\u0001 \\u003ce\\u0026f\\u003e\",\"none\":null}\n");
    json_object *back = json_tokener_parse(page), *s;
    assert_true(json_object_object_get_ex(back, "path", &s));
    assert_string_equal(json_object_get_string(s), "a/b \"c\" \\d\n\x01 <e&f>");
    json_object_put(back), json_object_put(o);
    free(text), free(page);
}

static void line_breaks_between_members(void **state) {
    (void)state;
    json_object *o = json_object_new_object(), *list = json_object_new_array(),
                *inner = json_object_new_object();
    json_object_object_add(inner, "v", json_object_new_int(1));
    json_object_object_add(o, "about", cs_jline_after(inner));
    json_object_object_add(o, "n", json_object_new_int(2));
    json_object_object_add(o, "x", cs_jnum(0.5));
    assert_int_equal(cs_jline_after_last(o), 0);
    for (int i = 0; i < 2; i++)
        json_object_array_add(list, cs_jline_before(json_object_new_int(i)));
    json_object_object_add(o, "list", cs_jline_after(list));
    json_object_object_add(o, "end", cs_jline_after(NULL));
    char *text = text_of(o, 0);
    assert_string_equal(text,
                        "{\"about\":{\"v\":1}\n,\"n\":2,\"x\":0.5\n,\"list\":[\n0,\n1]\n,\"end\":null\n}\n");
    json_object *back = json_tokener_parse(text), *v;
    assert_non_null(back);
    assert_true(json_object_object_get_ex(back, "x", &v));
    CHECK_ABS(json_object_get_double(v), 0.5, 0.0);
    assert_true(json_object_object_get_ex(back, "list", &v));
    assert_int_equal(json_object_array_length(v), 2);
    assert_int_equal(json_object_get_int(json_object_array_get_idx(v, 1)), 1);
    json_object_put(back), json_object_put(o);
    free(text);
}

static void keys_on_new_lines(void **state) {
    (void)state;
    static const char *const keys[] = {"b", "c/d", NULL};
    json_object *o = json_object_new_object(), *list = json_object_new_array();
    json_object_object_add(o, "a", cs_jline_after(cs_jnum(1.25)));
    json_object_array_add(list, cs_jstr("x\"y"));
    json_object_object_add(o, "b", list);
    json_object_object_add(o, "c/d", NULL);
    cs_jkeys_on_new_line(o, keys);
    char *text = text_of(o, 0);
    assert_string_equal(text, "{\"a\":1.25\n,\n\"b\":[\"x\\\"y\"],\n\"c/d\":null}\n");
    json_object *back = json_tokener_parse(text), *v;
    assert_non_null(back);
    assert_int_equal(json_object_object_length(back), 3);
    assert_true(json_object_object_get_ex(back, "b", &v));
    assert_string_equal(json_object_get_string(json_object_array_get_idx(v, 0)), "x\"y");
    json_object_put(back), json_object_put(o);
    free(text);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(numbers_keep_their_text),   cmocka_unit_test(number_lists_to_their_digits),
        cmocka_unit_test(strings_escaped_by_json_c), cmocka_unit_test(line_breaks_between_members),
        cmocka_unit_test(keys_on_new_lines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
