//! One run at a time in an output folder. A folder holds one run's `summary.json` and
//! `history.csv`, so two runs writing into it would leave files of both that each look complete.
//! A run holds the operating system's lock (`File::try_lock`: flock on Unix, LockFileEx on
//! Windows) on the folder's `.adit.lock` while it goes; the lock is let go when the run ends
//! however it ends (a kill included), so none is ever left stale. The file itself stays.

use std::path::Path;

/// The lock's file name in the output folder.
pub const LOCK_FILE: &str = ".adit.lock";

/// How long a lock found held is tried again before the folder is refused: a child forked while
/// this process held it keeps it until its exec (`FolderLock::take`).
const FORK_WINDOW: std::time::Duration = std::time::Duration::from_secs(2);

/// The folder held by this run, let go on drop.
#[derive(Debug)]
pub struct FolderLock {
    _file: std::fs::File,
}

impl FolderLock {
    /// Hold `dir` (which exists) for this run; an error when another run holds it.
    pub fn take(dir: &Path) -> anyhow::Result<FolderLock> {
        let path = dir.join(LOCK_FILE);
        let folder = |e: std::io::Error| anyhow::anyhow!("output folder {}: {e}", dir.display());
        let file = std::fs::OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&path)
            .map_err(folder)?;
        // A process that forks (to spawn a child) while it holds the lock shares it with the
        // child until the child's exec closes the file: a lock just let go may still be held for
        // that moment. A run that holds the folder holds it for the whole run, so waiting a
        // moment before refusing changes nothing else.
        let patience = std::time::Instant::now();
        let locked = loop {
            match file.try_lock() {
                Err(std::fs::TryLockError::WouldBlock) if patience.elapsed() < FORK_WINDOW => {
                    std::thread::sleep(std::time::Duration::from_millis(10));
                }
                other => break other,
            }
        };
        match locked {
            Ok(()) => Ok(FolderLock { _file: file }),
            Err(std::fs::TryLockError::WouldBlock) => anyhow::bail!(
                "output folder {}: another run is writing there (it holds {}); wait for it to \
                 end or write elsewhere (`--out`)",
                dir.display(),
                path.display()
            ),
            Err(std::fs::TryLockError::Error(e)) => Err(folder(e)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder held cannot be taken again (the second opening's lock conflicts with the first,
    /// in one process as across two) until the first lets it go.
    #[test]
    fn a_folder_is_held_by_one_run_at_a_time() {
        let dir = std::env::temp_dir().join(format!("adit-lock-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let held = FolderLock::take(&dir).unwrap();
        let refused = FolderLock::take(&dir).unwrap_err().to_string();
        assert!(
            refused.contains("another run") && refused.contains(LOCK_FILE),
            "{refused}"
        );
        drop(held);
        drop(FolderLock::take(&dir).unwrap());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
