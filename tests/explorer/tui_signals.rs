//! The explorer ended from outside by SIGTERM, SIGINT (sent with kill, not typed), SIGHUP and
//! SIGQUIT: the real binary in a pseudo-terminal of the test's own, killed once its first frame
//! is drawn, must write the restore sequences last (mouse reporting off, cursor shown, the
//! alternate screen left), take the terminal out of raw mode and exit with 128 + the signal's
//! number, the shell's convention for a process ended by a signal.
#![cfg(target_os = "linux")]

use std::fs::File;
use std::io::{Read, Write};
use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// crossterm's DisableMouseCapture: SGR, urxvt, any-event, button-event and normal reporting off.
const MOUSE_OFF: &[u8] = b"\x1b[?1006l\x1b[?1015l\x1b[?1003l\x1b[?1002l\x1b[?1000l";
/// Show the cursor (DECTCEM set).
pub const SHOW_CURSOR: &[u8] = b"\x1b[?25h";
/// Leave the alternate screen (xterm's private mode 1049 reset).
pub const LEAVE_ALTERNATE: &[u8] = b"\x1b[?1049l";
/// Enter the alternate screen.
const ENTER_ALTERNATE: &[u8] = b"\x1b[?1049h";

/// A pseudo-terminal of 80 x 24: the master side the test reads, the slave side the program's.
fn pty() -> (OwnedFd, OwnedFd) {
    let (mut master, mut slave) = (-1, -1);
    let size = libc::winsize {
        ws_row: 24,
        ws_col: 80,
        ws_xpixel: 0,
        ws_ypixel: 0,
    };
    // SAFETY: openpty writes two descriptors into the two ints; the name and the termios may be
    // null; the window size is read only.
    let done = unsafe {
        libc::openpty(
            &mut master,
            &mut slave,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            &size,
        )
    };
    assert_eq!(done, 0, "openpty: {}", std::io::Error::last_os_error());
    // SAFETY: both descriptors were just opened and are owned by nothing else.
    unsafe { (OwnedFd::from_raw_fd(master), OwnedFd::from_raw_fd(slave)) }
}

/// The terminal's local modes (`c_lflag`): Linux answers for the slave side on the master.
fn local_modes(master: &OwnedFd) -> libc::tcflag_t {
    // SAFETY: termios is plain data, filled by tcgetattr on an open descriptor.
    let mut t: libc::termios = unsafe { std::mem::zeroed() };
    assert_eq!(unsafe { libc::tcgetattr(master.as_raw_fd(), &mut t) }, 0);
    t.c_lflag
}

/// The real binary running in a pty of the test's own: what it writes is collected as it comes.
pub struct Explorer {
    master: OwnedFd,
    child: Child,
    written: Arc<Mutex<Vec<u8>>>,
    reader: JoinHandle<()>,
    deadline: Instant,
}

impl Explorer {
    /// Starts `wearlab ARGS` in `dir` (also its HOME) on an 80 x 24 pty and waits for its first
    /// frame, checking that the terminal is in raw mode.
    pub fn start(dir: &Path, args: &[&str]) -> Explorer {
        let (master, slave) = pty();
        let mut command = Command::new(assert_cmd::cargo::cargo_bin!("wearlab"));
        command
            .args(args)
            .current_dir(dir)
            .env("TERM", "xterm-256color")
            .env("HOME", dir)
            .env("XDG_DATA_HOME", dir)
            .stdin(Stdio::from(slave.try_clone().unwrap()))
            .stdout(Stdio::from(slave.try_clone().unwrap()))
            .stderr(Stdio::from(slave));
        // SAFETY: only async-signal-safe calls between fork and exec: a session of its own whose
        // controlling terminal is the pty (stdin), as a shell in a terminal emulator would have.
        unsafe {
            command.pre_exec(|| {
                if libc::setsid() < 0 || libc::ioctl(0, libc::TIOCSCTTY, 0) < 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
        let child = command.spawn().unwrap();
        // the slave's last copy outside the child goes with the command, so that reading the
        // master ends when the child has exited
        drop(command);
        let written = Arc::new(Mutex::new(Vec::new()));
        let reader = {
            let written = Arc::clone(&written);
            let mut file = File::from(master.try_clone().unwrap());
            std::thread::spawn(move || {
                let mut chunk = [0u8; 65536];
                while let Ok(n) = file.read(&mut chunk) {
                    if n == 0 {
                        break;
                    }
                    written.lock().unwrap().extend_from_slice(&chunk[..n]);
                }
            })
        };
        let explorer = Explorer {
            master,
            child,
            written,
            reader,
            deadline: Instant::now() + Duration::from_secs(30),
        };
        // the first frame ends with the key footer
        while !explorer
            .written
            .lock()
            .unwrap()
            .windows(b"q quit".len())
            .any(|w| w == b"q quit")
        {
            assert!(
                Instant::now() < explorer.deadline,
                "no first frame: {:?}",
                String::from_utf8_lossy(&explorer.written.lock().unwrap())
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        assert_eq!(
            local_modes(&explorer.master) & libc::ICANON,
            0,
            "the explorer runs in raw mode"
        );
        explorer
    }

    /// Types `bytes` (a key's escape sequence or text).
    pub fn type_bytes(&self, bytes: &[u8]) {
        let mut file = File::from(self.master.try_clone().unwrap());
        file.write_all(bytes).unwrap();
    }

    /// Resizes the window to `cols` x `rows` (the kernel sends the explorer SIGWINCH).
    pub fn resize(&self, cols: u16, rows: u16) {
        let size = libc::winsize {
            ws_row: rows,
            ws_col: cols,
            ws_xpixel: 0,
            ws_ypixel: 0,
        };
        // SAFETY: TIOCSWINSZ reads a winsize from the pointer, on an open descriptor.
        assert_eq!(
            unsafe { libc::ioctl(self.master.as_raw_fd(), libc::TIOCSWINSZ, &size) },
            0
        );
    }

    /// True once the explorer has exited (its own keys may quit it).
    pub fn exited(&mut self) -> bool {
        self.child.try_wait().unwrap().is_some()
    }

    /// Sends `signal` unless it has exited already, and returns what it wrote, how it exited and
    /// the terminal's local modes after.
    pub fn end(mut self, signal: i32) -> (Vec<u8>, ExitStatus, libc::tcflag_t) {
        if !self.exited() {
            let pid = i32::try_from(self.child.id()).unwrap();
            // SAFETY: a signal to the child this test started and has not reaped.
            assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
        }
        let status = loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                break status;
            }
            if Instant::now() > self.deadline + Duration::from_secs(30) {
                let _ = self.child.kill();
                panic!("signal {signal}: the explorer did not exit");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        self.reader.join().unwrap();
        let modes = local_modes(&self.master);
        let bytes = self.written.lock().unwrap().clone();
        (bytes, status, modes)
    }
}

/// What the explorer wrote until it exited, and how it exited, when `signal` arrived after its
/// first frame.
fn killed_by(signal: i32, mouse: bool) -> (Vec<u8>, ExitStatus, libc::tcflag_t) {
    let dir = tempfile::tempdir().unwrap();
    let args: &[&str] = if mouse { &["--mouse"] } else { &[] };
    Explorer::start(dir.path(), args).end(signal)
}

fn check(signal: i32) {
    for mouse in [false, true] {
        let (bytes, status, modes) = killed_by(signal, mouse);
        let lossy = String::from_utf8_lossy(&bytes[bytes.len().saturating_sub(200)..]).to_string();
        assert_eq!(status.code(), Some(128 + signal), "{status:?}");
        assert!(
            bytes
                .windows(ENTER_ALTERNATE.len())
                .any(|w| w == ENTER_ALTERNATE),
            "never on the alternate screen"
        );
        let tail = [
            if mouse { MOUSE_OFF } else { b"" },
            SHOW_CURSOR,
            LEAVE_ALTERNATE,
        ]
        .concat();
        assert!(
            bytes.ends_with(&tail),
            "signal {signal}, mouse {mouse}: does not end with the restore: {lossy:?}"
        );
        assert_eq!(
            modes & (libc::ICANON | libc::ECHO),
            libc::ICANON | libc::ECHO,
            "signal {signal}: the terminal is left in raw mode"
        );
    }
}

#[test]
fn sigterm_restores_the_terminal() {
    check(libc::SIGTERM);
}

#[test]
fn sigint_sent_as_a_signal_restores_the_terminal() {
    check(libc::SIGINT);
}

#[test]
fn sighup_restores_the_terminal() {
    check(libc::SIGHUP);
}

#[test]
fn sigquit_restores_the_terminal() {
    check(libc::SIGQUIT);
}
