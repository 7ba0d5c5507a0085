//! Whether the standard output was closed when the process started (`wearlab solve P >&-`).
//! Rust's runtime opens /dev/null on a closed standard descriptor before `main` runs, where a
//! result would be written and lost with exit 0; so the descriptor is looked at earlier, by a
//! function of the executable's initialisers (`.init_array`, run by the C runtime before `main`).

use std::sync::atomic::{AtomicBool, Ordering};

static CLOSED: AtomicBool = AtomicBool::new(false);

#[cfg(target_os = "linux")]
extern "C" fn look() {
    // SAFETY: fcntl(F_GETFD) only reads the descriptor table; it fails with EBADF on a
    // descriptor that is not open
    let closed = unsafe { libc::fcntl(libc::STDOUT_FILENO, libc::F_GETFD) } == -1;
    CLOSED.store(closed, Ordering::Relaxed);
}

#[cfg(target_os = "linux")]
#[used]
#[unsafe(link_section = ".init_array")]
static LOOK: extern "C" fn() = look;

/// True when stdout was not open at the start (always false where this cannot be seen).
pub fn closed() -> bool {
    CLOSED.load(Ordering::Relaxed)
}
