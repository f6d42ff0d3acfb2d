/* text_escape.h: text from files (scene tokens, mesh names) made safe to print on a terminal:
 * control bytes (C0, DEL, and C1 as UTF-8), invisible marks (a byte-order mark, zero-width and
 * bidirectional controls) and bytes that are not UTF-8 become \xNN (byte by byte), so that
 * no escape sequence or binary byte from an input reaches the terminal raw. */
#ifndef PREE_TEXT_ESCAPE_H
#define PREE_TEXT_ESCAPE_H

#include <stddef.h>

/* Copy src to dst (cap bytes, always terminated when cap > 0), escaping as above; a sequence
 * that does not fit whole is dropped. Returns dst. */
char *text_escape(const char *src, char *dst, size_t cap);

#endif
