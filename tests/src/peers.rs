//! Independent Modbus clients for the end-to-end tests: mbpoll and pymodbus, system packages
//! that `scripts/test.sh` installs, and socat's virtual serial cables ([`SocatPair`]).
//! Without them the tests that use them fail and say so.

use std::process::Command;

/// The path of a program that a test needs, or a panic that says how to get it.
#[track_caller]
pub fn required_program(name: &str) -> String {
    let found = Command::new("sh")
        .args(["-c", &format!("command -v {name}")])
        .output()
        .unwrap_or_else(|error| panic!("cannot run sh to look for {name}: {error}"));
    assert!(
        found.status.success(),
        "{name} is not installed: run scripts/test.sh, which installs mbpoll, python3-pymodbus and \
         socat"
    );
    String::from_utf8_lossy(&found.stdout).trim().to_owned()
}

/// A Python interpreter that can import what the peer script imports (pymodbus 3.0's server
/// and RTU framer, and serial_asyncio): `$RIVET_PYTHON`, Debian's `/usr/bin/python3` (whose
/// pymodbus the script is written for), or `python3` on the path.
#[track_caller]
pub fn python_with_pymodbus() -> String {
    let candidates = std::env::var("RIVET_PYTHON")
        .into_iter()
        .chain(["/usr/bin/python3".to_owned(), "python3".to_owned()]);
    for python in candidates {
        let imports = Command::new(&python)
            .args([
                "-c",
                "import pymodbus.server.async_io, pymodbus.framer.rtu_framer, serial_asyncio",
            ])
            .output();
        if imports.is_ok_and(|output| output.status.success()) {
            return python;
        }
    }
    panic!(
        "no python3 can import pymodbus: run scripts/test.sh, which installs mbpoll and \
         python3-pymodbus"
    );
}

/// Runs `program` with `args` to its end and returns its standard output, or panics with
/// everything it said when it fails.
#[track_caller]
pub fn run(program: &str, args: &[String]) -> String {
    let output = Command::new(program)
        .args(args)
        .output()
        .unwrap_or_else(|error| panic!("cannot run {program}: {error}"));
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    assert!(
        output.status.success(),
        "{program} {} failed with {}:\n{stdout}\n{}",
        args.join(" "),
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    stdout
}

/// A virtual serial cable: socat joining two pseudo-terminals under the names `master` and
/// `slave` in a directory the test chooses (`socat pty,raw,echo=0,link=DIR/master
/// pty,raw,echo=0,link=DIR/slave`).
///
/// Bytes written to one end are read at the other. [`SocatPair::kill`] is a pulled cable: the
/// names go, and a port open on either end reads end of file and fails to write;
/// [`SocatPair::restart`] makes new pseudo-terminals under the same names, as a USB adapter
/// that comes back. This machine's kernel refuses parity and 7 data bits on a pseudo-terminal,
/// so the lines are 8N1 or 8N2. Dropping the pair ends socat.
pub struct SocatPair {
    /// The end a master (mbpoll, the runtime's master) opens.
    pub master: std::path::PathBuf,
    /// The end a slave (the runtime's RTU slave, pymodbus's RTU server) opens.
    pub slave: std::path::PathBuf,
    /// The running socat, while the cable is plugged in.
    socat: Option<std::process::Child>,
}

/// How long socat may take to make its pseudo-terminals or to end.
const SOCAT_PATIENCE: std::time::Duration = std::time::Duration::from_secs(5);

impl SocatPair {
    /// Starts socat with the two names in `dir` and waits until both exist; panics, saying how to
    /// install socat, when it is missing.
    #[track_caller]
    pub fn start(dir: &std::path::Path) -> Self {
        let mut pair = Self {
            master: dir.join("master"),
            slave: dir.join("slave"),
            socat: None,
        };
        pair.restart();
        pair
    }

    /// Starts socat again (after [`SocatPair::kill`]) under the same names, and waits until
    /// they exist.
    #[track_caller]
    pub fn restart(&mut self) {
        self.kill();
        let socat = required_program("socat");
        let end = |path: &std::path::Path| format!("pty,raw,echo=0,link={}", path.display());
        let child = Command::new(socat)
            .args([end(&self.master), end(&self.slave)])
            .stdin(std::process::Stdio::null())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap_or_else(|error| panic!("cannot start socat: {error}"));
        self.socat = Some(child);
        let deadline = std::time::Instant::now() + SOCAT_PATIENCE;
        while !(self.master.exists() && self.slave.exists()) {
            assert!(
                std::time::Instant::now() < deadline,
                "socat made no pseudo-terminals at {} and {}",
                self.master.display(),
                self.slave.display()
            );
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
    }

    /// Ends socat (SIGTERM, so it removes its names) and waits until it has; does nothing when
    /// it is not running.
    pub fn kill(&mut self) {
        let Some(mut child) = self.socat.take() else {
            return;
        };
        let terminated = Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .is_ok_and(|status| status.success());
        let deadline = std::time::Instant::now() + SOCAT_PATIENCE;
        while terminated && std::time::Instant::now() < deadline {
            if matches!(child.try_wait(), Ok(Some(_))) {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        // A socat that ignored SIGTERM is killed outright, which leaves its names behind.
        let _ = child.kill();
        let _ = child.wait();
        let _ = std::fs::remove_file(&self.master);
        let _ = std::fs::remove_file(&self.slave);
    }
}

impl Drop for SocatPair {
    fn drop(&mut self) {
        self.kill();
    }
}

/// `runtime/tests/peers/pymodbus_server.py`: pymodbus as an independent Modbus slave, over TCP
/// or RTU, whose tables a test reads and sets through the script's standard input, and which
/// it can make slow or answer with exceptions. Dropping it ends the script.
pub struct PymodbusServer {
    /// The TCP port it listens on; 0 for an RTU server.
    pub port: u16,
    /// The script.
    child: std::process::Child,
    /// Its standard input, for the commands.
    commands: std::process::ChildStdin,
    /// Its standard output, line by line.
    replies: std::sync::mpsc::Receiver<String>,
    /// What it said on standard error so far (why it failed, pymodbus's warnings), for the
    /// panics that report it.
    said: std::sync::Arc<std::sync::Mutex<String>>,
    /// The thread collecting `said`, which ends with the script's standard error.
    said_reader: std::thread::JoinHandle<()>,
}

/// How long the script may take to start or to answer a command.
const PYMODBUS_PATIENCE: std::time::Duration = std::time::Duration::from_secs(10);

impl PymodbusServer {
    /// A Modbus TCP server on 127.0.0.1 on a port the system picks, then in
    /// [`PymodbusServer::port`]. One stopped and started again gets a new port: a test puts
    /// the fault proxy in front to keep the master's address (`fault_proxy::FaultProxy`).
    #[track_caller]
    pub fn tcp() -> Self {
        let mut server = Self::start(&["tcp".to_owned()]);
        let first = server.reply();
        server.port = first
            .strip_prefix("port ")
            .and_then(|port| port.parse().ok())
            .unwrap_or_else(|| {
                panic!(
                    "pymodbus_server.py tcp printed {first:?}; on standard error:\n{}",
                    server.errors()
                )
            });
        server
    }

    /// A Modbus RTU server on the serial port `path` (8 data bits, `parity` `'N'`, `'E'` or
    /// `'O'`) answering as each of `units`.
    #[track_caller]
    pub fn rtu(
        path: &std::path::Path,
        baud_rate: u32,
        parity: char,
        stop_bits: u8,
        units: &[u8],
    ) -> Self {
        let units: Vec<String> = units.iter().map(u8::to_string).collect();
        let mut server = Self::start(&[
            "rtu".to_owned(),
            path.display().to_string(),
            baud_rate.to_string(),
            parity.to_string(),
            stop_bits.to_string(),
            units.join(","),
        ]);
        let first = server.reply();
        assert_eq!(
            first,
            "ready",
            "pymodbus_server.py rtu printed {first:?}; on standard error:\n{}",
            server.errors()
        );
        server
    }

    /// The value at `address` of `table` (`co`, `di`, `hr`, `ir`, or `2.hr` for unit 2 of an
    /// RTU server).
    #[track_caller]
    pub fn get(&mut self, table: &str, address: u16) -> u16 {
        let reply = self.command(&format!("get {table} {address}"));
        reply
            .strip_prefix("value ")
            .and_then(|value| value.parse().ok())
            .unwrap_or_else(|| panic!("get {table} {address} answered {reply:?}"))
    }

    /// Sets the value at `address` of `table` (as in [`PymodbusServer::get`]).
    #[track_caller]
    pub fn set(&mut self, table: &str, address: u16, value: u16) {
        self.command(&format!("set {table} {address} {value}"));
    }

    /// Makes the server answer every later request `delay_ms` late (0: at once).
    #[track_caller]
    pub fn delay(&mut self, delay_ms: u64) {
        self.command(&format!("delay {delay_ms}"));
    }

    /// Makes the server answer every later request with exception 2, or stop doing so.
    #[track_caller]
    pub fn exceptions(&mut self, on: bool) {
        self.command(if on {
            "exceptions on"
        } else {
            "exceptions off"
        });
    }

    /// Sends one command line and returns the answer; panics on an `error` answer.
    #[track_caller]
    pub fn command(&mut self, line: &str) -> String {
        use std::io::Write;
        writeln!(self.commands, "{line}")
            .and_then(|()| self.commands.flush())
            .unwrap_or_else(|error| panic!("pymodbus_server.py took no command: {error}"));
        let reply = self.reply();
        assert!(!reply.starts_with("error"), "{line}: {reply}");
        reply
    }

    #[track_caller]
    fn start(arguments: &[String]) -> Self {
        let script = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../runtime/tests/peers/pymodbus_server.py"
        );
        let mut child = Command::new(python_with_pymodbus())
            .arg(script)
            .args(arguments)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap_or_else(|error| panic!("cannot start {script}: {error}"));
        let (Some(commands), Some(stdout), Some(stderr)) =
            (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            panic!("pymodbus_server.py has no standard input, output or error");
        };
        // Read all along, so that a chatty script never fills the pipe and blocks.
        let said = std::sync::Arc::new(std::sync::Mutex::new(String::new()));
        let errors = std::sync::Arc::clone(&said);
        let said_reader = std::thread::spawn(move || {
            use std::io::BufRead;
            for line in std::io::BufReader::new(stderr).lines() {
                let Ok(line) = line else { return };
                let mut errors = errors
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner);
                errors.push_str(&line);
                errors.push('\n');
            }
        });
        let (sender, replies) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            use std::io::BufRead;
            for line in std::io::BufReader::new(stdout).lines() {
                let Ok(line) = line else { return };
                if sender.send(line).is_err() {
                    return;
                }
            }
        });
        Self {
            port: 0,
            child,
            commands,
            replies,
            said,
            said_reader,
        }
    }

    /// What the script has said on standard error so far; when the script has ended, all of
    /// it (the reader ends with the pipe), waited for at most a second.
    fn errors(&mut self) -> String {
        if matches!(self.child.try_wait(), Ok(Some(_))) {
            let deadline = std::time::Instant::now() + std::time::Duration::from_secs(1);
            while !self.said_reader.is_finished() && std::time::Instant::now() < deadline {
                std::thread::sleep(std::time::Duration::from_millis(5));
            }
        }
        self.said
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone()
    }

    #[track_caller]
    fn reply(&mut self) -> String {
        match self.replies.recv_timeout(PYMODBUS_PATIENCE) {
            Ok(line) => line,
            Err(_) => {
                let status = self.child.try_wait();
                panic!(
                    "pymodbus_server.py said nothing (exit status {status:?}); on standard \
                     error:\n{}",
                    self.errors()
                )
            }
        }
    }
}

impl Drop for PymodbusServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
