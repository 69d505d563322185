//! Boxed handles with a magic tag.
//!
//! The C side sees an opaque type (`profsubd_mesh`); the allocation behind the pointer is a
//! [`Tagged`] value: a magic number first, then the Rust object. The tag is checked on every
//! entry and overwritten on free, so a pointer to another kind of handle or to garbage gives
//! `PROFSUBD_ERROR_INVALID_HANDLE` instead of undefined behaviour (for a freed handle this is
//! best effort: its memory may already be reused). To add a handle type: declare the opaque
//! marker struct, implement [`Handle`] for it with a new magic, and use [`into_raw`],
//! [`borrow`], [`borrow_mut`] and [`free`].

use std::ptr::{addr_of, addr_of_mut};

use crate::ffi::error::{set_last_error, FfiError, FfiResult};
use crate::ffi::status::profsubd_status::PROFSUBD_ERROR_INVALID_HANDLE;

/// Links an opaque C type to the Rust object behind it.
pub trait Handle {
    /// The Rust object the handle owns. `Send + Sync`: C callers may share handles between
    /// threads.
    type Inner: Send + Sync;
    /// Tag of a live handle of this type: unique among handle types.
    const MAGIC: u64;
    /// The C type name, for messages.
    const NAME: &'static str;
}

/// Tag written into a handle when it is freed.
const FREED: u64 = u64::from_le_bytes(*b"psd-FREE");

/// What a handle pointer points to: tag first (at offset 0 for every handle type).
#[repr(C)]
pub struct Tagged<T> {
    magic: u64,
    value: T,
}

/// Box `value` and return it as an owned handle for C.
pub fn into_raw<H: Handle>(value: H::Inner) -> *mut H {
    Box::into_raw(Box::new(Tagged {
        magic: H::MAGIC,
        value,
    }))
    .cast()
}

/// The tagged allocation behind `p`, if `p` is a live handle of type `H`.
unsafe fn check<H: Handle>(p: *const H, name: &str) -> FfiResult<*mut Tagged<H::Inner>> {
    if p.is_null() {
        return Err(FfiError::null_argument(name));
    }
    let t = p.cast::<Tagged<H::Inner>>().cast_mut();
    // Volatile: the check must read memory, even for a handle the compiler "knows" was freed.
    if !t.is_aligned() || std::ptr::read_volatile(addr_of!((*t).magic)) != H::MAGIC {
        return Err(FfiError::new(
            PROFSUBD_ERROR_INVALID_HANDLE,
            format!(
                "argument `{name}` is not a live {} (freed, or another kind of object)",
                H::NAME
            ),
        ));
    }
    Ok(t)
}

/// Borrow the object behind the handle `p` (argument `name`).
pub unsafe fn borrow<'a, H: Handle>(p: *const H, name: &str) -> FfiResult<&'a H::Inner> {
    check(p, name).map(|t| &(*t).value)
}

/// Borrow the object behind the handle `p` mutably.
pub unsafe fn borrow_mut<'a, H: Handle>(p: *mut H, name: &str) -> FfiResult<&'a mut H::Inner> {
    check(p, name).map(|t| &mut (*t).value)
}

/// Release the handle `p`: NULL is a no-op; a pointer that is not a live `H` is left alone
/// and reported as this thread's last error (a `_free` function has no status to return).
pub unsafe fn free<H: Handle>(p: *mut H) {
    if p.is_null() {
        return;
    }
    match check(p, "handle") {
        Ok(t) => {
            std::ptr::write_volatile(addr_of_mut!((*t).magic), FREED);
            drop(Box::from_raw(t));
        }
        Err(e) => set_last_error(&e.message),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ffi::error::last_error;

    struct Thing;
    impl Handle for Thing {
        type Inner = Vec<u32>;
        const MAGIC: u64 = 0x1234_5678_9abc_def0;
        const NAME: &'static str = "thing";
    }
    struct Other;
    impl Handle for Other {
        type Inner = u8;
        const MAGIC: u64 = 0x0fed_cba9_8765_4321;
        const NAME: &'static str = "other";
    }

    #[test]
    fn live_handles_pass_others_are_rejected() {
        let t = into_raw::<Thing>(vec![1, 2, 3]);
        let o = into_raw::<Other>(7);
        unsafe {
            assert_eq!(borrow(t, "t").unwrap(), &[1, 2, 3]);
            borrow_mut(t, "t").unwrap().push(4);
            assert_eq!(borrow(t, "t").unwrap().len(), 4);
            let e = borrow(o.cast::<Thing>(), "mesh").unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_INVALID_HANDLE);
            assert_eq!(
                e.message,
                "argument `mesh` is not a live thing (freed, or another kind of object)"
            );
            let garbage = [0u64; 8];
            let e = borrow(garbage.as_ptr().cast::<Thing>(), "t").unwrap_err();
            assert_eq!(e.status, PROFSUBD_ERROR_INVALID_HANDLE);
            let misaligned = garbage.as_ptr().cast::<u8>().add(3).cast::<Thing>();
            assert!(borrow(misaligned, "t").is_err());
            // Freeing a foreign pointer leaves it alone and says why.
            free(garbage.as_ptr().cast::<Thing>().cast_mut());
            assert!(last_error().contains("not a live thing"));
            free(std::ptr::null_mut::<Thing>());
            free(t);
            free(o);
        }
    }
}
