/* SPDX-License-Identifier: MIT */
/** @file
 * CS_API, the mark of the library's interface: the functions it marks are exported from libcablesim.so,
 * which hides every other symbol. Each public header includes this one. */
#ifndef CABLESIM_EXPORT_H
#define CABLESIM_EXPORT_H

/** Marks a function of the library's interface: exported from libcablesim.so, which hides the rest. */
#if defined(__GNUC__)
#define CS_API __attribute__((visibility("default")))
#else
#define CS_API
#endif

#endif
