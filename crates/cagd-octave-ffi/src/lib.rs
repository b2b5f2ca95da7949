//! The C ABI of the Octave package `cagd`: a static library linked into the package's
//! oct-file, and the only place of the package with `unsafe` code.
//!
//! # oct-file, not MEX
//! The gateway (`octave_pkg/src/__cagd__.cc`) is an **oct-file** compiled by `mkoctfile`, not a
//! MEX file, because the package is for Octave only and the oct-file API lets it
//! - borrow Octave's arrays without a copy (`NDArray::data`) and create the results in place
//!   (a zero-filled `NDArray` whose buffer the Rust side fills): the MEX API of Octave copies
//!   every `mxArray` crossing the boundary, which for a `1000 × 1000` grid costs more than
//!   evaluating it;
//! - see Octave's classes as they are (ranges, integer types, `single`, complex, sparse,
//!   logical, cells, structs, function handles), so that every wrong class is refused by name
//!   before anything is computed;
//! - raise errors with an identifier through `error_with_id`, after the Rust call returned.
//!
//! The price is that the oct-file must be compiled for the Octave it runs in, which
//! `pkg install` does anyway (the package builds from source).
//!
//! # The boundary
//! One entry point, [`cagd_call`] (C declarations in `include/cagd_octave_ffi.h`): a function
//! name, the arguments as a tree of [`CagdValue`] borrowing Octave's arrays, the number of
//! outputs, a [`CagdSink`] through which the outputs are allocated by Octave and filled here,
//! and an out-parameter for an error. Everything it does happens inside
//! [`std::panic::catch_unwind`]: a panic becomes the error `cagd:internal` and never unwinds
//! into C++. Conversely, nothing here calls back into Octave except the two sink callbacks,
//! which are `noexcept` on the C++ side and report failure by their return value, so no C++
//! exception or Octave error ever unwinds through Rust frames: the gateway raises the Octave
//! error itself, after [`cagd_call`] returned (and after copying and freeing the message with
//! [`cagd_error_free`]).
//!
//! # Unsafe code
//! Confined to this file: reading the argument tree (raw pointers and lengths given by the
//! gateway, turned into slices that live as long as the call), writing through the buffers the
//! sink returns, and handing the error strings across. Each `unsafe` block states the
//! guarantee it relies on. The functions themselves are `cagd_octave_pkg::call`, which is
//! `#![forbid(unsafe_code)]`, as is the core.
//!
//! # Ctrl-C
//! The sink's `interrupted` callback is asked every few milliseconds of long work (the
//! package's [`call_interruptible`](cagd_octave_pkg::call_interruptible)); the gateway reads
//! Octave's pending signals there (`octave_quit`, its exception kept) and, when the call
//! stopped, rethrows Octave's own interrupt after this call returned: Ctrl-C stops a package
//! function as it stops Octave's own.
//!
//! # The session's limits
//! The resource limits (`cagd_limits` in Octave) are one [`cagd::Limits`] value held here for
//! the Octave process and passed to every call.

use std::cell::RefCell;
use std::ffi::{c_char, c_int, c_void, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{LazyLock, Mutex, Once};

use cagd::Limits;
use cagd_octave_pkg::{Kind, PkgError, Real, Sink, Value};

/// `CAGD_REAL`: a real full double array.
pub const CAGD_REAL: i32 = 0;
/// `CAGD_CHAR`: a char array.
pub const CAGD_CHAR: i32 = 1;
/// `CAGD_CELL`: a cell array.
pub const CAGD_CELL: i32 = 2;
/// `CAGD_STRUCT`: a scalar struct.
pub const CAGD_STRUCT: i32 = 3;
/// `CAGD_OTHER`: any other class (its name in `text`).
pub const CAGD_OTHER: i32 = 4;
/// `CAGD_NUMERIC`: a real numeric or logical array of another class than full double
/// (`single`, integers, `logical`, sparse): its class name in `text`, its values converted to
/// double in `real`.
pub const CAGD_NUMERIC: i32 = 5;

/// Deepest nesting of cells and structs read (the gateway stops at the same depth).
pub const MAX_DEPTH: usize = 64;

/// One argument (`struct cagd_value` in the header).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct CagdValue {
    /// One of the `CAGD_*` kinds.
    pub kind: i32,
    /// Entries of `dims`.
    pub ndims: usize,
    /// Octave's size.
    pub dims: *const usize,
    /// `CAGD_REAL`: `prod(dims)` doubles.
    pub real: *const f64,
    /// `CAGD_CHAR`: the bytes; `CAGD_OTHER`: the class name.
    pub text: *const c_char,
    /// Bytes of `text`.
    pub text_len: usize,
    /// `CAGD_CELL`: the items; `CAGD_STRUCT`: the field values.
    pub items: *const CagdValue,
    /// `CAGD_STRUCT`: the NUL-terminated field names.
    pub names: *const *const c_char,
    /// Entries of `items` (and `names`).
    pub n_items: usize,
}

/// The allocation of a real output: returns its zero-filled data or null.
pub type RealFn = unsafe extern "C" fn(
    ctx: *mut c_void,
    index: usize,
    ndims: usize,
    dims: *const usize,
) -> *mut f64;

/// The allocation of a cell array of strings: returns 0 or non-zero on failure.
pub type StringsFn = unsafe extern "C" fn(
    ctx: *mut c_void,
    index: usize,
    ndims: usize,
    dims: *const usize,
    texts: *const *const c_char,
    lens: *const usize,
) -> c_int;

/// Whether the user asked to stop: non-zero for yes; safe on any thread.
pub type InterruptedFn = unsafe extern "C" fn(ctx: *mut c_void) -> c_int;

/// The outputs (`struct cagd_sink` in the header).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct CagdSink {
    /// The gateway's context, passed back to the callbacks.
    pub ctx: *mut c_void,
    /// Allocates a real output.
    pub real: Option<RealFn>,
    /// Sets a cell array of strings.
    pub strings: Option<StringsFn>,
    /// Asks whether the user asked to stop (Ctrl-C); null: never.
    pub interrupted: Option<InterruptedFn>,
}

/// The gateway's interrupt callback with its context, asked by the computation between
/// chunks of its work (on the calling thread, or on a worker thread of a parallel loop).
struct Interrupt {
    asked: Option<InterruptedFn>,
    ctx: *mut c_void,
}

// SAFETY: the header requires the callback to be safe on any thread; the context pointer is
// only handed back to it, never dereferenced here.
unsafe impl Sync for Interrupt {}

impl Interrupt {
    fn asked(&self) -> bool {
        match self.asked {
            // SAFETY: the gateway's callback, noexcept and safe on any thread (header).
            Some(f) => unsafe { f(self.ctx) != 0 },
            None => false,
        }
    }
}

/// An error (`struct cagd_error` in the header): identifier and message, owned by this
/// library until [`cagd_error_free`].
#[repr(C)]
#[derive(Debug)]
pub struct CagdError {
    /// `cagd:<kind>`.
    pub id: *mut c_char,
    /// The one-line message.
    pub message: *mut c_char,
}

/// The limits of the Octave session.
static LIMITS: LazyLock<Mutex<Limits>> = LazyLock::new(|| Mutex::new(Limits::default()));

/// A slice of `len` elements at `ptr`; empty for `len == 0` whatever `ptr` is.
///
/// # Safety
/// For `len > 0`, `ptr` must point to `len` initialised elements that stay valid and unchanged
/// for `'a`.
unsafe fn slice<'a, T>(ptr: *const T, len: usize) -> Result<&'a [T], PkgError> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(PkgError::new(
            Kind::Internal,
            "__cagd__: null argument data",
        ));
    }
    // SAFETY: non-null, and the caller guarantees `len` valid elements for `'a`.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// The argument tree as [`Value`]s borrowing the gateway's arrays.
///
/// # Safety
/// `v` and everything it points to (as the header describes) must stay valid for `'a`.
unsafe fn value<'a>(v: &'a CagdValue, depth: usize) -> Result<Value<'a>, PkgError> {
    if depth > MAX_DEPTH {
        return Ok(Value::Other {
            class: "cell or struct nested too deep",
        });
    }
    // SAFETY (all blocks below): the gateway passes, for each kind, the pointers and lengths
    // the header documents, valid until `cagd_call` returns, which outlives `'a`.
    let dims = unsafe { slice(v.dims, v.ndims) }?;
    let numel = dims
        .iter()
        .try_fold(1usize, |acc, &d| acc.checked_mul(d))
        .ok_or_else(|| PkgError::new(Kind::Internal, "__cagd__: size overflows"))?;
    let text =
        || -> Result<&'a [u8], PkgError> { unsafe { slice(v.text.cast::<u8>(), v.text_len) } };
    let items = || -> Result<&'a [CagdValue], PkgError> { unsafe { slice(v.items, v.n_items) } };
    match v.kind {
        CAGD_REAL if dims.len() >= 2 => Ok(Value::Real(Real {
            dims,
            data: unsafe { slice(v.real, numel) }?,
        })),
        CAGD_CHAR if dims.len() >= 2 && v.text_len == numel => Ok(Value::Char {
            dims,
            bytes: text()?,
        }),
        CAGD_CELL if dims.len() >= 2 && v.n_items == numel => Ok(Value::Cell {
            dims,
            items: items()?
                .iter()
                .map(|item| unsafe { value(item, depth + 1) })
                .collect::<Result<_, _>>()?,
        }),
        CAGD_STRUCT => Ok(Value::Struct {
            fields: unsafe { fields(v, depth) }?,
        }),
        CAGD_OTHER => Ok(Value::Other {
            class: std::str::from_utf8(text()?).unwrap_or("?"),
        }),
        CAGD_NUMERIC if dims.len() >= 2 => Ok(Value::Numeric {
            class: std::str::from_utf8(text()?).unwrap_or("?"),
            real: Real {
                dims,
                data: unsafe { slice(v.real, numel) }?,
            },
        }),
        kind => Err(PkgError::new(
            Kind::Internal,
            format!("__cagd__: malformed argument (kind {kind})"),
        )),
    }
}

/// The fields of a `CAGD_STRUCT` value: its names with their values.
///
/// # Safety
/// As [`value`].
unsafe fn fields<'a>(
    v: &'a CagdValue,
    depth: usize,
) -> Result<Vec<(&'a str, Value<'a>)>, PkgError> {
    // SAFETY: the names and items of a struct, as the header documents, valid for `'a`.
    let names = unsafe { slice(v.names, v.n_items) }?;
    let items = unsafe { slice(v.items, v.n_items) }?;
    let mut fields = Vec::with_capacity(names.len());
    for (name, item) in names.iter().zip(items) {
        if name.is_null() {
            return Err(PkgError::new(Kind::Internal, "__cagd__: null field name"));
        }
        // SAFETY: a non-null NUL-terminated field name, valid for the call.
        let name = unsafe { CStr::from_ptr(*name) }.to_str().unwrap_or("?");
        fields.push((name, unsafe { value(item, depth + 1) }?));
    }
    Ok(fields)
}

/// Arguments held without an allocation.
const FEW: usize = 8;

/// Up to [`FEW`] values in place (a fixed array of which the first `len` are set).
struct FewValues<'a> {
    slots: [std::mem::MaybeUninit<Value<'a>>; FEW],
    len: usize,
}

impl<'a> FewValues<'a> {
    fn new() -> Self {
        FewValues {
            slots: [const { std::mem::MaybeUninit::uninit() }; FEW],
            len: 0,
        }
    }

    /// Appends `v`; the caller keeps to [`FEW`] values.
    fn push(&mut self, v: Value<'a>) {
        self.slots[self.len].write(v);
        self.len += 1;
    }

    fn as_slice(&self) -> &[Value<'a>] {
        // SAFETY: the first `len` slots are initialised (`push`), and `MaybeUninit<T>` has the
        // layout of `T`.
        unsafe { std::slice::from_raw_parts(self.slots.as_ptr().cast::<Value<'a>>(), self.len) }
    }
}

impl Drop for FewValues<'_> {
    fn drop(&mut self) {
        for slot in &mut self.slots[..self.len] {
            // SAFETY: initialised by `push`, dropped once.
            unsafe { slot.assume_init_drop() };
        }
    }
}

/// The gateway's sink as a [`Sink`].
struct FfiSink<'s> {
    raw: &'s CagdSink,
}

impl Sink for FfiSink<'_> {
    fn real(&mut self, index: usize, dims: &[usize]) -> Result<&mut [f64], PkgError> {
        let len: usize = dims.iter().product();
        let memory = || {
            PkgError::new(
                Kind::Memory,
                format!(
                    "out of memory for output {} ({})",
                    index + 1,
                    cagd_octave_pkg::value::size_str(dims)
                ),
            )
        };
        let f = self.raw.real.ok_or_else(memory)?;
        // SAFETY: the gateway's callback is noexcept and returns null or the zero-filled data of
        // a new array of `prod(dims)` doubles, valid until `cagd_call` returns; only this
        // slice writes to it.
        let ptr = unsafe { f(self.raw.ctx, index, dims.len(), dims.as_ptr()) };
        if ptr.is_null() {
            return Err(memory());
        }
        if len == 0 {
            return Ok(&mut []);
        }
        // SAFETY: as above; `len` elements, exclusively ours for the lifetime of `&mut self`.
        Ok(unsafe { std::slice::from_raw_parts_mut(ptr, len) })
    }

    fn strings(&mut self, index: usize, dims: &[usize], items: &[String]) -> Result<(), PkgError> {
        let memory = || {
            PkgError::new(
                Kind::Memory,
                format!("out of memory for output {}", index + 1),
            )
        };
        let f = self.raw.strings.ok_or_else(memory)?;
        let ptrs: Vec<*const c_char> = items.iter().map(|s| s.as_ptr().cast()).collect();
        let lens: Vec<usize> = items.iter().map(String::len).collect();
        // SAFETY: the callback is noexcept, reads `prod(dims)` texts of the given lengths
        // (the strings live until it returns) and copies them.
        let status = unsafe {
            f(
                self.raw.ctx,
                index,
                dims.len(),
                dims.as_ptr(),
                ptrs.as_ptr(),
                lens.as_ptr(),
            )
        };
        if status != 0 {
            return Err(memory());
        }
        Ok(())
    }
}

thread_local! {
    /// Where the last panic of this thread happened (`file:line`), for the error message.
    static PANIC_AT: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Replaces the default panic hook (which prints a backtrace into the Octave session) by one
/// that only records where the panic happened; the message reaches Octave as the error
/// `cagd:internal`. Installed once, on the first call.
fn quiet_panics() {
    static HOOK: Once = Once::new();
    HOOK.call_once(|| {
        std::panic::set_hook(Box::new(|info| {
            let at = info
                .location()
                .map(|l| format!("{}:{}", l.file(), l.line()));
            PANIC_AT.with(|p| *p.borrow_mut() = at);
        }));
    });
}

/// The text of a panic's payload.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown fault".into())
}

/// A C string of `s` (NUL bytes replaced).
fn c_string(s: &str) -> *mut c_char {
    CString::new(s.replace('\0', " "))
        .unwrap_or_default()
        .into_raw()
}

/// Calls the package function `name` with `nargs` arguments, `nargout` outputs (0 counts as
/// 1), writing the outputs through `sink`. Returns 0, or 1 with `error` set (free it with
/// [`cagd_error_free`]).
///
/// # Safety
/// As the header says: `name` points to `name_len` bytes; `args` to `nargs` values whose
/// pointers are valid (and unchanged) until this returns; `sink` to a sink whose callbacks do
/// not unwind; `error` to writable storage.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_call(
    name: *const c_char,
    name_len: usize,
    args: *const CagdValue,
    nargs: usize,
    nargout: c_int,
    sink: *const CagdSink,
    error: *mut CagdError,
) -> c_int {
    let run = || -> Result<(), PkgError> {
        // SAFETY: the caller's guarantees above.
        let name = unsafe { name_str(name, name_len) }?;
        let raw_args = unsafe { slice(args, nargs) }?;
        // Up to 8 arguments without an allocation (a call for one point costs about a
        // microsecond; an allocation is a tenth of it).
        let (mut few, mut many) = (FewValues::new(), Vec::new());
        // SAFETY: the caller's guarantees above.
        let values = unsafe { read_args(raw_args, &mut few, &mut many) }?;
        if sink.is_null() {
            return Err(PkgError::new(Kind::Internal, "__cagd__: no sink"));
        }
        // SAFETY: non-null, valid for the call.
        let raw = unsafe { &*sink };
        let interrupt = Interrupt {
            asked: raw.interrupted,
            ctx: raw.ctx,
        };
        let mut out = FfiSink { raw };
        if name == "__panic__" {
            // The boundary's own test: a panic must come back as cagd:internal.
            panic!("a deliberate panic, to test the boundary");
        }
        let mut limits = LIMITS.lock().unwrap_or_else(|p| p.into_inner());
        let nargout = usize::try_from(nargout).unwrap_or(0);
        let asked = || interrupt.asked();
        cagd_octave_pkg::call_interruptible(name, (values, nargout), &mut limits, &asked, &mut out)
    };
    quiet_panics();
    match catch_unwind(AssertUnwindSafe(run)).unwrap_or_else(|payload| Err(caught(payload))) {
        Ok(()) => 0,
        Err(e) => {
            if !error.is_null() {
                // SAFETY: the caller gives writable storage for one `CagdError`.
                unsafe {
                    *error = CagdError {
                        id: c_string(&e.identifier()),
                        message: c_string(&e.message),
                    };
                }
            }
            1
        }
    }
}

/// The name of a package function: `len` bytes at `name`, UTF-8 (`?` if not).
///
/// # Safety
/// `name` points to `len` bytes valid for `'a` (or `len` is 0).
unsafe fn name_str<'a>(name: *const c_char, len: usize) -> Result<&'a str, PkgError> {
    // SAFETY: the caller's guarantee.
    let name = unsafe { slice(name.cast::<u8>(), len) }?;
    Ok(if name.is_ascii() {
        // SAFETY: ASCII is UTF-8.
        unsafe { std::str::from_utf8_unchecked(name) }
    } else {
        std::str::from_utf8(name).unwrap_or("?")
    })
}

/// The arguments as [`Value`]s: in `few` (no allocation) for up to [`FEW`] of them, else in
/// `many`.
///
/// # Safety
/// As [`value`], for every argument.
unsafe fn read_args<'a, 'v>(
    raw: &'a [CagdValue],
    few: &'v mut FewValues<'a>,
    many: &'v mut Vec<Value<'a>>,
) -> Result<&'v [Value<'a>], PkgError> {
    if raw.len() <= FEW {
        for v in raw {
            // SAFETY: the caller's guarantee.
            few.push(unsafe { value(v, 0) }?);
        }
        return Ok(few.as_slice());
    }
    for v in raw {
        // SAFETY: the caller's guarantee.
        many.push(unsafe { value(v, 0) }?);
    }
    Ok(many)
}

/// A caught panic as the error `cagd:internal`, with where it happened.
fn caught(payload: Box<dyn std::any::Any + Send>) -> PkgError {
    let at = PANIC_AT
        .with(|p| p.borrow_mut().take())
        .map(|l| format!(" ({l})"))
        .unwrap_or_default();
    PkgError::new(
        Kind::Internal,
        format!(
            "__cagd__: internal error: {}{at}; this is a bug in the cagd package",
            panic_message(payload.as_ref())
        ),
    )
}

/// Frees the strings of an error set by [`cagd_call`] (and nulls them).
///
/// # Safety
/// `error` is null or points to a `CagdError` whose strings are null or were set by
/// [`cagd_call`] and not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_error_free(error: *mut CagdError) {
    if error.is_null() {
        return;
    }
    // SAFETY: the caller's guarantee; each string came from `CString::into_raw`.
    unsafe {
        for s in [&mut (*error).id, &mut (*error).message] {
            if !s.is_null() {
                drop(CString::from_raw(*s));
                *s = std::ptr::null_mut();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sink over vectors, through the C callbacks.
    struct Outputs {
        real: Vec<(usize, Vec<usize>, Vec<f64>)>,
        interrupted: Option<InterruptedFn>,
        asked: std::sync::atomic::AtomicUsize,
    }

    impl Outputs {
        fn new() -> Self {
            Outputs {
                real: vec![],
                interrupted: None,
                asked: std::sync::atomic::AtomicUsize::new(0),
            }
        }
    }

    /// Says "stop" from the third question on (as Ctrl-C pressed during the work).
    unsafe extern "C" fn stop_on_third(ctx: *mut c_void) -> c_int {
        // SAFETY: the test passes its `Outputs`; only the atomic counter is touched.
        let out = unsafe { &*ctx.cast::<Outputs>() };
        let k = out.asked.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        c_int::from(k >= 2)
    }

    unsafe extern "C" fn real_cb(
        ctx: *mut c_void,
        index: usize,
        ndims: usize,
        dims: *const usize,
    ) -> *mut f64 {
        // SAFETY: the test passes its `Outputs` and a valid size vector.
        let out = unsafe { &mut *ctx.cast::<Outputs>() };
        let dims = unsafe { std::slice::from_raw_parts(dims, ndims) }.to_vec();
        let n = dims.iter().product();
        out.real.push((index, dims, vec![0.0; n]));
        out.real
            .last_mut()
            .map_or(std::ptr::null_mut(), |r| r.2.as_mut_ptr())
    }

    fn real_value(dims: &[usize], data: &[f64]) -> CagdValue {
        CagdValue {
            kind: CAGD_REAL,
            ndims: dims.len(),
            dims: dims.as_ptr(),
            real: data.as_ptr(),
            text: std::ptr::null(),
            text_len: 0,
            items: std::ptr::null(),
            names: std::ptr::null(),
            n_items: 0,
        }
    }

    fn call(name: &str, args: &[CagdValue], out: &mut Outputs) -> Result<(), (String, String)> {
        let sink = CagdSink {
            ctx: (out as *mut Outputs).cast(),
            real: Some(real_cb),
            strings: None,
            interrupted: out.interrupted,
        };
        let mut error = CagdError {
            id: std::ptr::null_mut(),
            message: std::ptr::null_mut(),
        };
        // SAFETY: every pointer is valid for the call.
        let status = unsafe {
            cagd_call(
                name.as_ptr().cast(),
                name.len(),
                args.as_ptr(),
                args.len(),
                1,
                &sink,
                &mut error,
            )
        };
        if status == 0 {
            return Ok(());
        }
        // SAFETY: set by cagd_call.
        let texts = unsafe {
            (
                CStr::from_ptr(error.id).to_string_lossy().into_owned(),
                CStr::from_ptr(error.message).to_string_lossy().into_owned(),
            )
        };
        unsafe { cagd_error_free(&mut error) };
        assert!(error.id.is_null() && error.message.is_null());
        Err(texts)
    }

    #[test]
    fn a_call_through_the_c_abi() {
        let p = [0.0, 0.0, 0.0, 0.0, 2.0, 2.0, 8.0, 2.0, 0.0, 4.0, 0.0, 0.0];
        let n = [3.0];
        let (pd, nd) = ([3usize, 4], [1usize, 1]);
        let args = [real_value(&pd, &p), real_value(&nd, &n)];
        let mut out = Outputs::new();
        call("deCasteljau", &args, &mut out).unwrap();
        assert_eq!(out.real[0].1, vec![3, 3]);
        assert_eq!(&out.real[0].2[3..6], &[3.5, 1.5, 0.75]);
    }

    #[test]
    fn errors_and_panics_come_back_as_values() {
        let mut out = Outputs::new();
        let (id, message) = call("deCasteljau", &[], &mut out).unwrap_err();
        assert_eq!(id, "cagd:nargin");
        assert!(
            message.starts_with("deCasteljau: called with 0 argument(s)"),
            "{message}"
        );
        let (id, message) = call("__panic__", &[], &mut out).unwrap_err();
        assert_eq!(id, "cagd:internal");
        assert!(message.contains("a deliberate panic"), "{message}");
        let class = "int32";
        let other = CagdValue {
            kind: CAGD_OTHER,
            text: class.as_ptr().cast(),
            text_len: class.len(),
            ..real_value(&[1, 1], &[0.0])
        };
        let (id, message) = call("tenzor", &[other], &mut out).unwrap_err();
        assert_eq!(id, "cagd:class");
        assert!(message.contains("B: int32 is not accepted"), "{message}");
    }

    #[test]
    fn long_work_asks_the_callback_and_stops() {
        // deCasteljau of a degree-600 curve at 100 points: chunks of 11 points, the
        // callback asked before each; it says stop on the third question.
        let p = vec![1.0; 601];
        let (pd, nd) = ([1usize, 601], [1usize, 1]);
        let n = [100.0];
        let args = [real_value(&pd, &p), real_value(&nd, &n)];
        let mut out = Outputs::new();
        out.interrupted = Some(stop_on_third);
        let (id, message) = call("deCasteljau", &args, &mut out).unwrap_err();
        assert_eq!(
            (id.as_str(), message.as_str()),
            ("cagd:interrupted", "deCasteljau: interrupted")
        );
        assert_eq!(out.asked.load(std::sync::atomic::Ordering::SeqCst), 3);
        // Without the callback the same call runs to its end.
        let mut out = Outputs::new();
        call("deCasteljau", &args, &mut out).unwrap();
        assert_eq!(out.real[0].2.len(), 100);
        assert!(out.real[0].2.iter().all(|&x| (x - 1.0).abs() < 1e-12));
    }
}
