//! Checks of the raw pointers C callers pass, so that no exported function repeats them.
//!
//! Each helper turns a pointer plus its count into a Rust reference or slice after checking
//! NULL (`PROFSUBD_ERROR_NULL_ARGUMENT`), alignment and byte size (`PROFSUBD_ERROR_INVALID_ARGUMENT`).
//! Output locations are checked first and written last, so a failed call writes nothing.

use std::ffi::{c_char, CStr};
use std::mem::{size_of, MaybeUninit};
use std::path::PathBuf;

use crate::ffi::error::{FfiError, FfiResult};
use crate::ffi::handle::{self, Handle};
use crate::ffi::panic::status_call;
use crate::ffi::status::profsubd_status::{
    self, PROFSUBD_ERROR_BUFFER_TOO_SMALL, PROFSUBD_ERROR_NULL_ARGUMENT,
};

fn check_aligned<T>(p: *const T, name: &str) -> FfiResult<()> {
    if p.is_aligned() {
        Ok(())
    } else {
        Err(FfiError::invalid_argument(format!(
            "argument `{name}` is not aligned to {} bytes",
            std::mem::align_of::<T>()
        )))
    }
}

/// `len` elements of `T` as a byte count, if that is a size an allocation can have.
fn byte_size<T>(len: usize, name: &str) -> FfiResult<usize> {
    len.checked_mul(size_of::<T>())
        .filter(|&b| b <= isize::MAX as usize)
        .ok_or_else(|| {
            FfiError::invalid_argument(format!(
                "`{name}` would hold {len} elements of {} bytes: larger than any buffer can be",
                size_of::<T>()
            ))
        })
}

/// `p` as a shared reference.
pub unsafe fn arg_ref<'a, T>(p: *const T, name: &str) -> FfiResult<&'a T> {
    if p.is_null() {
        return Err(FfiError::null_argument(name));
    }
    check_aligned(p, name)?;
    Ok(&*p)
}

/// `len` elements at `p` (NULL allowed when `len` is 0).
pub unsafe fn arg_slice<'a, T>(p: *const T, len: usize, name: &str) -> FfiResult<&'a [T]> {
    byte_size::<T>(len, name)?;
    if len == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(FfiError::new(
            PROFSUBD_ERROR_NULL_ARGUMENT,
            format!("argument `{name}` is NULL but its count is {len}"),
        ));
    }
    check_aligned(p, name)?;
    Ok(std::slice::from_raw_parts(p, len))
}

/// A NUL-terminated path. The empty string is rejected.
pub unsafe fn arg_path(p: *const c_char, name: &str) -> FfiResult<PathBuf> {
    if p.is_null() {
        return Err(FfiError::null_argument(name));
    }
    let bytes = CStr::from_ptr(p).to_bytes();
    if bytes.is_empty() {
        return Err(FfiError::invalid_argument(format!(
            "argument `{name}` is an empty path"
        )));
    }
    Ok(path_from_bytes(bytes))
}

#[cfg(unix)]
fn path_from_bytes(bytes: &[u8]) -> PathBuf {
    use std::os::unix::ffi::OsStrExt;
    PathBuf::from(std::ffi::OsStr::from_bytes(bytes))
}

#[cfg(not(unix))]
fn path_from_bytes(bytes: &[u8]) -> PathBuf {
    PathBuf::from(String::from_utf8_lossy(bytes).into_owned())
}

/// A single output location, checked on entry and written once at the end.
pub struct Out<'a, T>(&'a mut MaybeUninit<T>);

impl<T> Out<'_, T> {
    /// Store the result.
    pub fn write(self, value: T) {
        self.0.write(value);
    }
}

/// The required output location `p`.
pub unsafe fn arg_out<'a, T>(p: *mut T, name: &str) -> FfiResult<Out<'a, T>> {
    if p.is_null() {
        return Err(FfiError::null_argument(name));
    }
    check_aligned(p, name)?;
    Ok(Out(&mut *p.cast::<MaybeUninit<T>>()))
}

/// An optional output location (NULL means the caller does not want it).
pub unsafe fn arg_out_opt<'a, T>(p: *mut T, name: &str) -> FfiResult<Option<Out<'a, T>>> {
    if p.is_null() {
        Ok(None)
    } else {
        arg_out(p, name).map(Some)
    }
}

/// The checked caller side of a copy-out call (`capacity` items, optional `*needed`).
///
/// Protocol: the caller's buffers hold `capacity` items (each item is `width` elements of
/// its buffer); a buffer may be NULL only when `capacity` is 0. If the data has more items
/// than `capacity`, the call fails with `PROFSUBD_ERROR_BUFFER_TOO_SMALL` after writing the
/// item count to `*needed` (if `needed` is not NULL) and leaves the buffers untouched; on
/// success the data is copied and `*needed` is set to the item count.
pub struct CopyOut<'a> {
    capacity: usize,
    needed: Option<Out<'a, usize>>,
}

impl<'a> CopyOut<'a> {
    /// Check `needed`; buffers are checked with [`CopyOut::buffer`].
    pub unsafe fn new(capacity: usize, needed: *mut usize) -> FfiResult<Self> {
        Ok(CopyOut {
            capacity,
            needed: arg_out_opt(needed, "needed")?,
        })
    }

    /// The caller buffer `p` of `capacity` items of `width` elements each.
    pub unsafe fn buffer<T>(
        &self,
        p: *mut T,
        width: usize,
        name: &str,
    ) -> FfiResult<&'a mut [MaybeUninit<T>]> {
        let len = self.capacity.checked_mul(width).ok_or_else(|| {
            FfiError::invalid_argument(format!("capacity {} is absurdly large", self.capacity))
        })?;
        byte_size::<T>(len, name)?;
        if len == 0 {
            return Ok(&mut []);
        }
        if p.is_null() {
            return Err(FfiError::new(
                PROFSUBD_ERROR_NULL_ARGUMENT,
                format!(
                    "argument `{name}` is NULL but capacity is {}",
                    self.capacity
                ),
            ));
        }
        check_aligned(p, name)?;
        Ok(std::slice::from_raw_parts_mut(p.cast(), len))
    }

    /// Finish the call for `count` items: fail if they do not fit, else run `fill` (which
    /// writes the buffers) and report `count`. `unit` names the items in the message.
    pub fn finish(self, count: usize, unit: &str, fill: impl FnOnce()) -> FfiResult<()> {
        if count > self.capacity {
            if let Some(n) = self.needed {
                n.write(count);
            }
            return Err(FfiError::new(
                PROFSUBD_ERROR_BUFFER_TOO_SMALL,
                format!(
                    "buffer too small: capacity is {} {unit}, {count} needed",
                    self.capacity
                ),
            ));
        }
        fill();
        if let Some(n) = self.needed {
            n.write(count);
        }
        Ok(())
    }
}

/// Write `src` into the start of `dst` (which [`CopyOut::finish`] checked is long enough).
pub fn fill<T>(dst: &mut [MaybeUninit<T>], src: impl IntoIterator<Item = T>) {
    for (d, s) in dst.iter_mut().zip(src) {
        d.write(s);
    }
}

/// A whole copy-out export of one array read from a handle: under the panic guard, borrow
/// `handle` (its pointer and argument name), check `needed` and the buffer `out` (pointer and
/// argument name) of `capacity` items of `width` elements each, then `items` gives the item
/// count and the elements, copied by the [`CopyOut`] protocol (`unit` names the items in the
/// "buffer too small" message). `items` runs after every argument check, so its errors come
/// last; its elements are only read when they fit.
pub unsafe fn copy_slice<'a, H: Handle, T, I: IntoIterator<Item = T>>(
    (handle, handle_name): (*const H, &str),
    (out, out_name, capacity, needed): (*mut T, &str, usize, *mut usize),
    (width, unit): (usize, &str),
    items: impl FnOnce(&'a H::Inner) -> FfiResult<(usize, I)>,
) -> profsubd_status
where
    H::Inner: 'a,
{
    status_call(|| {
        let source = handle::borrow::<H>(handle, handle_name)?;
        let c = CopyOut::new(capacity, needed)?;
        let buf = c.buffer(out, width, out_name)?;
        let (count, elements) = items(source)?;
        c.finish(count, unit, || fill(buf, elements))
    })
}

/// The item count and the elements of `items` (one element per item), for [`copy_slice`].
pub fn all_of<T: Copy>(items: &[T]) -> (usize, std::iter::Copied<std::slice::Iter<'_, T>>) {
    (items.len(), items.iter().copied())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::status::profsubd_status::*;

    #[test]
    fn slices_check_null_size_and_alignment() {
        let data = [1u32, 2, 3, 4];
        unsafe {
            assert_eq!(arg_slice(data.as_ptr(), 4, "a").unwrap(), &data);
            assert!(arg_slice::<u32>(std::ptr::null(), 0, "a")
                .unwrap()
                .is_empty());
            let e = arg_slice::<u32>(std::ptr::null(), 2, "face_sizes").unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_NULL_ARGUMENT);
            assert_eq!(
                e.message,
                "argument `face_sizes` is NULL but its count is 2"
            );
            let e = arg_slice(data.as_ptr(), usize::MAX / 2, "a").unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_INVALID_ARGUMENT);
            let misaligned = data.as_ptr().cast::<u8>().add(1).cast::<u32>();
            let e = arg_slice(misaligned, 1, "a").unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_INVALID_ARGUMENT);
            assert!(e.message.contains("not aligned to 4 bytes"));
        }
    }

    #[test]
    fn paths_reject_null_and_empty() {
        unsafe {
            assert_eq!(
                arg_path(std::ptr::null(), "path").unwrap_err().status,
                PROFSUBD_ERROR_NULL_ARGUMENT
            );
            assert_eq!(
                arg_path(c"".as_ptr(), "path").unwrap_err().status,
                PROFSUBD_ERROR_INVALID_ARGUMENT
            );
            assert_eq!(
                arg_path(c"a/b.obj".as_ptr(), "path").unwrap(),
                PathBuf::from("a/b.obj")
            );
        }
    }

    /// A handle type for the [`copy_slice`] tests.
    struct Values {
        _private: [u8; 0],
    }

    impl Handle for Values {
        type Inner = Vec<u32>;
        const MAGIC: u64 = u64::from_le_bytes(*b"psd-TEST");
        const NAME: &'static str = "values";
    }

    /// `copy_slice` over the handle's values, 2 elements per item (3 items).
    unsafe fn copy_pairs(
        h: *const Values,
        out: *mut u32,
        capacity: usize,
        needed: *mut usize,
    ) -> profsubd_status {
        copy_slice(
            (h, "v"),
            (out, "out", capacity, needed),
            (2, "pairs"),
            |v| Ok((v.len() / 2, v.iter().copied())),
        )
    }

    #[test]
    fn copy_slice_checks_handle_then_needed_then_buffer_then_copies() {
        use crate::ffi::error::last_error;
        let h = handle::into_raw::<Values>(vec![1, 2, 3, 4, 5, 6]);
        let mut buf = [9u32; 6];
        let mut needed = 77usize;
        unsafe {
            // The handle comes first, even with a NULL buffer that could not hold anything.
            let st = copy_pairs(std::ptr::null(), std::ptr::null_mut(), 5, &mut needed);
            assert_eq!(
                (st, last_error().as_str()),
                (PROFSUBD_ERROR_NULL_ARGUMENT, "argument `v` is NULL")
            );
            let misaligned = buf.as_mut_ptr().cast::<u8>().add(1).cast::<usize>();
            let st = copy_pairs(h, std::ptr::null_mut(), 5, misaligned);
            assert_eq!(st, PROFSUBD_ERROR_INVALID_ARGUMENT);
            let st = copy_pairs(h, std::ptr::null_mut(), 1, &mut needed);
            assert_eq!(st, PROFSUBD_ERROR_NULL_ARGUMENT);
            assert_eq!(needed, 77, "nothing written on an argument error");
            // Size query: capacity 0, NULL buffer.
            let st = copy_pairs(h, std::ptr::null_mut(), 0, &mut needed);
            assert_eq!((st, needed), (PROFSUBD_ERROR_BUFFER_TOO_SMALL, 3));
            // Too small: needed written, buffer untouched.
            needed = 0;
            let st = copy_pairs(h, buf.as_mut_ptr(), 2, &mut needed);
            assert_eq!(
                (st, needed, buf),
                (PROFSUBD_ERROR_BUFFER_TOO_SMALL, 3, [9; 6])
            );
            assert_eq!(
                last_error(),
                "buffer too small: capacity is 2 pairs, 3 needed"
            );
            // Fits: copied, needed = the item count; `needed` may be NULL.
            let st = copy_pairs(h, buf.as_mut_ptr(), 3, &mut needed);
            assert_eq!((st, needed, buf), (PROFSUBD_OK, 3, [1, 2, 3, 4, 5, 6]));
            assert_eq!(
                copy_pairs(h, buf.as_mut_ptr(), 3, std::ptr::null_mut()),
                PROFSUBD_OK
            );
            // An error of the accessor is the call's error, with nothing written.
            needed = 77;
            let st = copy_slice(
                (h.cast_const(), "v"),
                (buf.as_mut_ptr(), "out", 3, &mut needed),
                (2, "pairs"),
                |_| Err::<(usize, [u32; 0]), _>(FfiError::invalid_argument("no pairs today")),
            );
            assert_eq!((st, needed), (PROFSUBD_ERROR_INVALID_ARGUMENT, 77));
            handle::free(h);
        }
    }

    #[test]
    fn copy_out_reports_needed_and_leaves_buffer_untouched() {
        let mut buf = [7u32; 2];
        let mut needed = 0usize;
        unsafe {
            let c = CopyOut::new(2, &mut needed).unwrap();
            let b = c.buffer(buf.as_mut_ptr(), 1, "out").unwrap();
            let e = c.finish(3, "indices", || fill(b, [1, 2, 3])).unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_BUFFER_TOO_SMALL);
            assert_eq!(
                e.message,
                "buffer too small: capacity is 2 indices, 3 needed"
            );
        }
        assert_eq!((buf, needed), ([7, 7], 3));
        unsafe {
            let c = CopyOut::new(2, &mut needed).unwrap();
            let b = c.buffer(buf.as_mut_ptr(), 1, "out").unwrap();
            c.finish(1, "indices", || fill(b, [5])).unwrap();
        }
        assert_eq!((buf, needed), ([5, 7], 1));
        unsafe {
            let c = CopyOut::new(1, std::ptr::null_mut()).unwrap();
            let e = c
                .buffer::<u32>(std::ptr::null_mut(), 2, "vertices")
                .unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_NULL_ARGUMENT);
            let c = CopyOut::new(usize::MAX, std::ptr::null_mut()).unwrap();
            let e = c.buffer(buf.as_mut_ptr(), 2, "vertices").unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_INVALID_ARGUMENT);
        }
    }
}
