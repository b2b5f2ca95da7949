/* cagd_octave_ffi.h -- the C ABI of the Rust static library cagd-octave-ffi, which the oct-file
 * __cagd__ of the Octave package cagd links (octave_pkg/src/__cagd__.cc).
 *
 * One entry point, cagd_call: the name of a package function, its arguments as a tree of
 * cagd_value (borrowing Octave's arrays), the number of outputs, and a sink through which the
 * Rust side asks for the output arrays and fills them. It returns 0, or non-zero with an Octave
 * error identifier and message in *error, which the caller frees with cagd_error_free after
 * copying them. No Rust panic leaves cagd_call (each is caught and reported as cagd:internal),
 * and the Rust side never raises an Octave error: the caller does, after cagd_call returned.
 * Long work asks the sink's `interrupted` callback every few milliseconds and stops (the
 * error cagd:interrupted) when it answers non-zero: the caller then raises Octave's interrupt.
 *
 * The layouts must match the #[repr(C)] structs of crates/cagd-octave-ffi/src/lib.rs.
 */
#ifndef CAGD_OCTAVE_FFI_H
#define CAGD_OCTAVE_FFI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum cagd_kind
{
  CAGD_REAL = 0,   /* real full double array: dims, real */
  CAGD_CHAR = 1,   /* char array: dims, text/text_len (bytes, column-major) */
  CAGD_CELL = 2,   /* cell array: dims, items/n_items (column-major) */
  CAGD_STRUCT = 3, /* scalar struct: items/n_items values, names (NUL-terminated) */
  CAGD_OTHER = 4,  /* any other class: text/text_len holds its name */
  CAGD_NUMERIC = 5 /* real single, integer, logical or sparse array: text/text_len holds its
                      class name, dims/real its values converted to double */
};

typedef struct cagd_value
{
  int32_t kind;
  size_t ndims;                    /* number of entries of dims (>= 2 for arrays) */
  const size_t *dims;              /* Octave's size () */
  const double *real;              /* CAGD_REAL, CAGD_NUMERIC: prod (dims) doubles, column-major */
  const char *text;                /* CAGD_CHAR: the bytes; CAGD_OTHER, CAGD_NUMERIC: the class */
  size_t text_len;
  const struct cagd_value *items;  /* CAGD_CELL: the items; CAGD_STRUCT: the field values */
  const char *const *names;        /* CAGD_STRUCT: the field names */
  size_t n_items;
} cagd_value;

/* The outputs. The callbacks must not throw (they return NULL / non-zero on failure).
 * real: a new zero-filled real array of size dims as output `index`; returns its data
 *       (valid until the call returns), NULL if it could not be allocated.
 * strings: a cell array of size dims holding the texts as char rows as output `index`;
 *       returns 0, non-zero on failure.
 * interrupted: non-zero when the user asked to stop (Ctrl-C); asked every few milliseconds of
 *       long work, from the calling thread or another one (it must be safe on any thread);
 *       may be NULL (never interrupted). */
typedef struct cagd_sink
{
  void *ctx;
  double *(*real) (void *ctx, size_t index, size_t ndims, const size_t *dims);
  int (*strings) (void *ctx, size_t index, size_t ndims, const size_t *dims,
                  const char *const *texts, const size_t *lens);
  int (*interrupted) (void *ctx);
} cagd_sink;

/* An error: Octave identifier ("cagd:shape") and one-line message, NUL-terminated, owned by
 * the Rust side until cagd_error_free. */
typedef struct cagd_error
{
  char *id;
  char *message;
} cagd_error;

int cagd_call (const char *name, size_t name_len, const cagd_value *args, size_t nargs,
               int nargout, const cagd_sink *sink, cagd_error *error);

void cagd_error_free (cagd_error *error);

#ifdef __cplusplus
}
#endif

#endif
