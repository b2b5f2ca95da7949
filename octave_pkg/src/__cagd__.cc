// __cagd__.cc -- the oct-file of the Octave package cagd: a thin gateway to the Rust library
// cagd-octave-ffi (crates/cagd-octave-ffi, C ABI in cagd_octave_ffi.h).
//
//   [out1, out2, ...] = __cagd__ (NAME, arg1, arg2, ...)
//
// calls the package function NAME. The arguments are described to the Rust side as a tree of
// cagd_value that borrows Octave's own arrays (no copy); the results are Octave arrays created
// here, zero-filled, and filled by the Rust side through the sink callbacks (no copy either).
//
// The octave-nurbs twins of octave-nurbs' own oct-files and evaluators (cagd_bspeval,
// cagd_basisfun, cagd_basisfunder, cagd_bspderiv, cagd_findspan, cagd_nrbeval) are builtins
// of this oct-file as well (autoloaded by the PKG_ADD lines below): one call for one point
// then costs one builtin call, as the octave-nurbs oct-files do. Their .m files in inst/ hold
// the documentation and the test blocks; build.sh generates the docstrings here from them
// (cagd_twin_docs.h) and ships their test blocks as NAME.cc-tst instead of the .m files (a .m
// file of a builtin's name on the path misleads Octave 7's lookup of function handles).
//
// Errors: the Rust side returns an identifier ("cagd:shape") and a message; this gateway raises
// the Octave error with error_with_id only after cagd_call has returned, so no C++ exception
// ever unwinds through Rust frames, and the callbacks below are noexcept. A Rust panic is caught
// on the Rust side and comes back as the error cagd:internal.
//
// Ctrl-C: long work on the Rust side asks the sink's `interrupted` callback every few
// milliseconds. On Octave's thread the callback runs octave_quit (), which handles a pending
// SIGINT by throwing Octave's interrupt exception; the callback keeps that exception and
// answers "stop", the Rust call returns, and the gateway rethrows the exception: the function
// stops exactly as Octave's own builtins stop on Ctrl-C (back to the prompt, not an error a
// try/catch sees). Asked from another thread, the callback only reads whether the stop was
// already seen.

#include <cstring>
#include <algorithm>
#include <atomic>
#include <exception>
#include <list>
#include <thread>
#include <tuple>
#include <typeinfo>
#include <string>
#include <utility>
#include <vector>

#include <octave/oct.h>
#include <octave/Cell.h>
#include <octave/oct-map.h>
#include <octave/ov-re-mat.h>
#include <octave/quit.h>

#include "cagd_octave_ffi.h"
#include "cagd_twin_docs.h"

namespace
{
  // Deepest nesting of cells and structs described (as MAX_DEPTH on the Rust side).
  const std::size_t max_depth = 64;

  // Everything the argument tree points into, alive until the call returns, at stable
  // addresses. A call of a few scalars and arrays (the usual one) allocates nothing here:
  // scalars and sizes go to fixed buffers, and the lists, used only for what those do not
  // hold (converted arrays, texts, cells, structs), allocate nothing until used.
  struct arena
  {
    double scalars[16];
    std::size_t n_scalars = 0;
    std::size_t dims[48];
    std::size_t n_dims = 0;
    std::list<double> more_scalars;
    std::list<std::vector<std::size_t>> more_dims;
    std::list<NDArray> arrays;
    std::list<charNDArray> chars;
    std::list<std::string> texts;
    std::list<std::vector<cagd_value>> children;
    std::list<std::vector<const char *>> names;

    const double *
    keep_scalar (double x)
    {
      if (n_scalars < sizeof scalars / sizeof scalars[0])
        {
          scalars[n_scalars] = x;
          return &scalars[n_scalars++];
        }
      more_scalars.push_back (x);
      return &more_scalars.back ();
    }

    // The sizes of one value, contiguous.
    std::size_t *
    keep_dims (std::size_t n)
    {
      if (n_dims + n <= sizeof dims / sizeof dims[0])
        {
          n_dims += n;
          return &dims[n_dims - n];
        }
      more_dims.emplace_back (n);
      return more_dims.back ().data ();
    }
  };

  // The array of a full real double matrix, borrowed (no copy, no allocation); nullptr for
  // any other value (scalars, ranges, diagonal matrices, other classes).
  const NDArray *
  full_array (const octave_value& v)
  {
    const octave_base_value *rep = v.internal_rep ();
    if (typeid (*rep) != typeid (octave_matrix))     // cheaper than a dynamic_cast
      return nullptr;
    return &static_cast<const octave_matrix *> (rep)->matrix_ref ();
  }

  const std::size_t *
  keep_dims (arena& a, const dim_vector& dv)
  {
    std::size_t *d = a.keep_dims (dv.ndims ());
    for (int i = 0; i < dv.ndims (); i++)
      d[i] = static_cast<std::size_t> (dv(i));
    return d;
  }

  // The class of a refused value, as the messages name it.
  std::string
  class_of (const octave_value& v)
  {
    if (! v.is_defined ())
      return "undefined";
    std::string c = v.class_name ();
    if (v.isstruct ())
      return "struct array";
    if (v.issparse ())
      c = "sparse " + c;
    if (v.iscomplex ())
      c = "complex " + c;
    return c;
  }

  void
  other (cagd_value& out, arena& a, const std::string& cls)
  {
    a.texts.push_back (cls);
    out.kind = CAGD_OTHER;
    out.text = a.texts.back ().data ();
    out.text_len = a.texts.back ().size ();
  }

  void
  describe (const octave_value& v, cagd_value& out, arena& a, std::size_t depth)
  {
    std::memset (&out, 0, sizeof out);
    if (depth > max_depth)
      {
        other (out, a, "cell or struct nested too deep");
        return;
      }
    if (! v.is_defined ())
      {
        other (out, a, "undefined");
        return;
      }
    if (v.is_real_scalar () && v.is_double_type ())
      {
        // A double scalar: its value, without an NDArray or a dim_vector (each of which
        // allocates).
        out.real = a.keep_scalar (v.double_value ());
        std::size_t *d = a.keep_dims (2);
        d[0] = d[1] = 1;
        out.dims = d;
        out.kind = CAGD_REAL;
        out.ndims = 2;
        return;
      }
    if (v.is_double_type () && v.isreal () && ! v.issparse () && ! v.iscomplex ())
      {
        // A full double matrix lends its own array (no copy); ranges and diagonal matrices
        // have none and are converted.
        const NDArray *arr = full_array (v);
        if (! arr)
          {
            a.arrays.push_back (v.array_value ());
            arr = &a.arrays.back ();
          }
        out.kind = CAGD_REAL;
        out.ndims = arr->ndims ();
        out.dims = keep_dims (a, arr->dims ());
        out.real = arr->data ();
        return;
      }
    const dim_vector dv = v.dims ();
    if ((v.isnumeric () || v.islogical ()) && v.isreal ())
      {
        // single, integer, logical, sparse: converted to double, the class kept for the
        // octave-nurbs twins (every other function refuses it by its class).
        a.arrays.push_back (v.array_value ());
        const NDArray& arr = a.arrays.back ();
        a.texts.push_back (class_of (v));
        out.kind = CAGD_NUMERIC;
        out.ndims = dv.ndims ();
        out.dims = keep_dims (a, dv);
        out.real = arr.data ();
        out.text = a.texts.back ().data ();
        out.text_len = a.texts.back ().size ();
      }
    else if (v.is_char_matrix () || v.is_string ())
      {
        a.chars.push_back (v.char_array_value ());
        const charNDArray& chr = a.chars.back ();
        out.kind = CAGD_CHAR;
        out.ndims = dv.ndims ();
        out.dims = keep_dims (a, dv);
        out.text = chr.data ();
        out.text_len = static_cast<std::size_t> (chr.numel ());
      }
    else if (v.iscell ())
      {
        const Cell c = v.cell_value ();
        std::vector<cagd_value> items (c.numel ());
        for (octave_idx_type i = 0; i < c.numel (); i++)
          describe (c(i), items[i], a, depth + 1);
        a.children.push_back (std::move (items));
        out.kind = CAGD_CELL;
        out.ndims = dv.ndims ();
        out.dims = keep_dims (a, dv);
        out.items = a.children.back ().data ();
        out.n_items = a.children.back ().size ();
      }
    else if (v.isstruct () && v.numel () == 1)
      {
        const octave_scalar_map m = v.scalar_map_value ();
        const string_vector keys = m.fieldnames ();
        std::vector<cagd_value> items (keys.numel ());
        std::vector<const char *> names (keys.numel ());
        for (octave_idx_type i = 0; i < keys.numel (); i++)
          {
            a.texts.push_back (keys(i));
            names[i] = a.texts.back ().c_str ();
            describe (m.contents (keys(i)), items[i], a, depth + 1);
          }
        a.children.push_back (std::move (items));
        a.names.push_back (std::move (names));
        out.kind = CAGD_STRUCT;
        out.items = a.children.back ().data ();
        out.names = a.names.back ().data ();
        out.n_items = a.children.back ().size ();
      }
    else
      other (out, a, class_of (v));
  }

  // The outputs, created by the callbacks and returned once the Rust call is done.
  dim_vector
  size_of (std::size_t ndims, const std::size_t *dims)
  {
    if (ndims == 2)                    // one allocation instead of two
      return dim_vector (static_cast<octave_idx_type> (dims[0]),
                         static_cast<octave_idx_type> (dims[1]));
    dim_vector dv;
    dv.resize (ndims < 2 ? 2 : static_cast<int> (ndims), 1);
    for (std::size_t i = 0; i < ndims; i++)
      dv(i) = static_cast<octave_idx_type> (dims[i]);
    return dv;
  }

  // The outputs: real arrays (a Matrix for 2 dimensions, the cheaper object, else an
  // NDArray) that own their data while Rust fills them — an Octave value made at once would
  // copy a 1 x 1 array into a scalar — and cells of strings as Octave values. The first few
  // in place, the others in lists (nothing allocated for the usual call). An array made
  // without a value is zero-filled once by its allocation (Array's elements are
  // value-initialized); with the value 0.0 it would be filled a second time.
  struct outputs
  {
    static const std::size_t few = 6;
    alignas (Matrix) unsigned char slots[few][sizeof (Matrix) > sizeof (NDArray)
                                               ? sizeof (Matrix) : sizeof (NDArray)];
    bool is_matrix[few];
    std::size_t index[few];
    std::size_t n = 0;
    std::list<std::pair<std::size_t, NDArray>> more;
    std::list<std::pair<std::size_t, octave_value>> others;
    // Ctrl-C: Octave's thread, the exception octave_quit () threw there, and whether the
    // work was told to stop (read from any thread).
    std::thread::id octave_thread = std::this_thread::get_id ();
    std::exception_ptr interrupt;
    std::atomic<bool> stopped { false };

    double *
    add_real (std::size_t i, std::size_t ndims, const std::size_t *dims)
    {
      if (n < few && ndims == 2)
        {
          Matrix *m = new (slots[n]) Matrix (static_cast<octave_idx_type> (dims[0]),
                                             static_cast<octave_idx_type> (dims[1]));
          is_matrix[n] = true;
          index[n++] = i;
          return m->fortran_vec ();
        }
      if (n < few)
        {
          NDArray *a = new (slots[n]) NDArray (size_of (ndims, dims));
          is_matrix[n] = false;
          index[n++] = i;
          return a->fortran_vec ();
        }
      more.emplace_back (std::piecewise_construct, std::forward_as_tuple (i),
                         std::forward_as_tuple (size_of (ndims, dims)));
      return more.back ().second.fortran_vec ();
    }

    octave_value
    value (std::size_t k) const
    {
      if (is_matrix[k])
        return octave_value (*reinterpret_cast<const Matrix *> (slots[k]));
      return octave_value (*reinterpret_cast<const NDArray *> (slots[k]));
    }

    ~outputs ()
    {
      for (std::size_t k = 0; k < n; k++)
        if (is_matrix[k])
          reinterpret_cast<Matrix *> (slots[k])->~Matrix ();
        else
          reinterpret_cast<NDArray *> (slots[k])->~NDArray ();
    }
  };


  extern "C" double *
  sink_real (void *ctx, std::size_t index, std::size_t ndims, const std::size_t *dims) noexcept
  {
    try
      {
        outputs& out = *static_cast<outputs *> (ctx);
        return out.add_real (index, ndims, dims);
      }
    catch (...)
      {
        return nullptr;
      }
  }

  // Whether the user pressed Ctrl-C: on Octave's thread, Octave's own check (octave_quit
  // throws its interrupt exception for a pending SIGINT; other signals it handles and
  // returns), the exception kept for the gateway to rethrow; on another thread only whether
  // that already happened.
  extern "C" int
  sink_interrupted (void *ctx) noexcept
  {
    outputs& out = *static_cast<outputs *> (ctx);
    if (out.stopped.load ())
      return 1;
    if (std::this_thread::get_id () != out.octave_thread || ! octave_signal_caught)
      return 0;
    try
      {
        octave_quit ();
        return 0;
      }
    catch (...)
      {
        out.interrupt = std::current_exception ();
        out.stopped.store (true);
        return 1;
      }
  }

  extern "C" int
  sink_strings (void *ctx, std::size_t index, std::size_t ndims, const std::size_t *dims,
                const char *const *texts, const std::size_t *lens) noexcept
  {
    try
      {
        outputs& out = *static_cast<outputs *> (ctx);
        Cell c (size_of (ndims, dims));
        for (octave_idx_type i = 0; i < c.numel (); i++)
          c(i) = octave_value (std::string (texts[i], lens[i]));
        out.others.emplace_back (index, octave_value (c));
        return 0;
      }
    catch (...)
      {
        return 1;
      }
  }
}

// The package function NAME called with args(first:end): the arguments described, the Rust
// call, its error raised or its outputs returned.
static octave_value_list
call_package (const char *name, std::size_t name_len, const octave_value_list& args,
              octave_idx_type first, int nargout)
{
  arena a;
  // The top-level values: inline for up to 8 arguments.
  cagd_value few[8];
  std::vector<cagd_value> many;
  const std::size_t nvals = static_cast<std::size_t> (args.length () - first);
  if (nvals > 8)
    many.resize (nvals);
  cagd_value *values = nvals > 8 ? many.data () : few;
  for (octave_idx_type i = first; i < args.length (); i++)
    describe (args(i), values[i - first], a, 0);

  outputs out;
  const cagd_sink sink = { &out, sink_real, sink_strings, sink_interrupted };
  cagd_error err = { nullptr, nullptr };
  const int status = cagd_call (name, name_len, values, nvals, nargout, &sink, &err);
  if (out.interrupt)
    {
      // Ctrl-C: Octave's own interrupt, whatever the call returned.
      cagd_error_free (&err);
      std::rethrow_exception (out.interrupt);
    }
  if (status != 0)
    {
      // Copy and free the Rust strings first: error_with_id does not return.
      const std::string id = err.id ? err.id : "cagd:internal";
      const std::string message = err.message ? err.message : "__cagd__: unknown error";
      cagd_error_free (&err);
      error_with_id (id.c_str (), "%s", message.c_str ());
    }

  // The list of outputs at its size at once.
  std::size_t n_out = 0;
  for (std::size_t k = 0; k < out.n; k++)
    n_out = std::max (n_out, out.index[k] + 1);
  for (const auto& v : out.more)
    n_out = std::max (n_out, v.first + 1);
  for (const auto& v : out.others)
    n_out = std::max (n_out, v.first + 1);
  if (n_out == 1 && out.n == 1)
    return octave_value_list (out.value (0));
  octave_value_list retval (static_cast<octave_idx_type> (n_out), octave_value ());
  for (std::size_t k = 0; k < out.n; k++)
    retval(out.index[k]) = out.value (k);
  for (const auto& v : out.more)
    retval(v.first) = octave_value (v.second);
  for (const auto& v : out.others)
    retval(v.first) = v.second;
  return retval;
}

DEFUN_DLD (__cagd__, args, nargout,
           "-*- texinfo -*-\n\
@deftypefn {} {[@dots{}] =} __cagd__ (@var{name}, @dots{})\n\
Internal gateway of the cagd package: calls the package function @var{name}.\n\
Use the package's functions (@code{help cagd_bezier}, @code{help deCasteljau}, @dots{}).\n\
@end deftypefn")
{
  if (args.length () < 1 || ! args(0).is_string ())
    error_with_id ("cagd:nargin", "__cagd__: the first argument must be a function name");
  const std::string name = args(0).string_value ();
  return call_package (name.data (), name.size (), args, 1, nargout);
}

// PKG_ADD: autoload ("cagd_bspeval", "__cagd__.oct");
DEFUN_DLD (cagd_bspeval, args, nargout, CAGD_DOC_cagd_bspeval)
{
  return call_package ("cagd_bspeval", sizeof "cagd_bspeval" - 1, args, 0, nargout);
}

// PKG_ADD: autoload ("cagd_basisfun", "__cagd__.oct");
DEFUN_DLD (cagd_basisfun, args, nargout, CAGD_DOC_cagd_basisfun)
{
  return call_package ("cagd_basisfun", sizeof "cagd_basisfun" - 1, args, 0, nargout);
}

// PKG_ADD: autoload ("cagd_basisfunder", "__cagd__.oct");
DEFUN_DLD (cagd_basisfunder, args, nargout, CAGD_DOC_cagd_basisfunder)
{
  return call_package ("cagd_basisfunder", sizeof "cagd_basisfunder" - 1, args, 0, nargout);
}

// PKG_ADD: autoload ("cagd_bspderiv", "__cagd__.oct");
DEFUN_DLD (cagd_bspderiv, args, nargout, CAGD_DOC_cagd_bspderiv)
{
  return call_package ("cagd_bspderiv", sizeof "cagd_bspderiv" - 1, args, 0, nargout);
}

// PKG_ADD: autoload ("cagd_findspan", "__cagd__.oct");
DEFUN_DLD (cagd_findspan, args, nargout, CAGD_DOC_cagd_findspan)
{
  return call_package ("cagd_findspan", sizeof "cagd_findspan" - 1, args, 0, nargout);
}

// PKG_ADD: autoload ("cagd_nrbeval", "__cagd__.oct");
DEFUN_DLD (cagd_nrbeval, args, nargout, CAGD_DOC_cagd_nrbeval)
{
  return call_package ("cagd_nrbeval", sizeof "cagd_nrbeval" - 1, args, 0, nargout);
}
