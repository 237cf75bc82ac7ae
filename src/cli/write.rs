//! Writing a build's files into the output folder: atomically, never through a symlink, one
//! build at a time, and with the manifest (`.tmm-outputs`) of what the build wrote.
//!
//! The order of [`write_outputs`] is what makes a failure harmless:
//! 1. take the folder's lock (`.tmm-lock`), waiting for another build that holds it;
//! 2. write every file to a temporary file beside its place and sync it; a failure here (a
//!    full disk, `ulimit -f`) removes the temporary files and leaves the folder as it was;
//! 3. record in the manifest every name that is or will be ours (the previous build's and this
//!    one's), so that whatever happens next, the next build knows what it may remove;
//! 4. rename each temporary file over its place: a reader sees the old file or the new one,
//!    never a part, and a symlink in the folder is replaced, not followed;
//! 5. remove the previous build's files this build did not write, then record this build's
//!    list.
//!
//! Temporary files come from the `tempfile` crate (`NamedTempFile` in the output folder and
//! `persist`) rather than hand-written code: it creates each with `O_EXCL` under a random
//! name, retrying on a collision, so a planted symlink is never followed and neither a
//! crashed build's leftover nor a recycled process id can collide; it removes the file on
//! every error path (its `Drop`); and it is already in the dependency tree (through proptest).

use anyhow::{Context, Result, bail};
use std::collections::BTreeSet;
use std::fs::{self, File, OpenOptions, TryLockError};
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};
use tempfile::NamedTempFile;

/// The file in the output folder that lists what the last build wrote, so that the next
/// build removes what it no longer writes (and nothing else).
pub const MANIFEST: &str = ".tmm-outputs";

/// The file in the output folder a build locks while it writes. It is never removed: removing
/// a lock file lets a waiting build lock the removed file while a third locks a new one.
pub const LOCK: &str = ".tmm-lock";

/// What marks a temporary file of ours: `.sheet1.svg.tmm-tmp-AbC123`.
pub const TEMP_MARK: &str = ".tmm-tmp-";

/// The largest manifest read: a hand-edited or planted one cannot make a build read for ever.
const MANIFEST_LIMIT: u64 = 1 << 20;

/// Writes `files` (name, bytes) into `dir`, creating it, replacing each file atomically and
/// removing the files the previous build listed and this one does not write.
pub fn write_outputs(dir: &Path, files: &[(String, Vec<u8>)]) -> Result<()> {
    check_names(files)?;
    fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let _lock = lock_folder(dir)?;
    remove_leftover_temps(dir);
    let previous = read_manifest(dir);
    let temps = files.iter().map(|(name, bytes)| write_temp(dir, name, bytes)).collect::<Result<Vec<_>>>()?;
    sync_together(dir, &temps, files)?;
    let now: BTreeSet<String> = files.iter().map(|(name, _)| name.clone()).collect();
    if !now.is_subset(&previous) {
        write_manifest(dir, &previous.union(&now).cloned().collect())?;
    }
    for (temp, (name, _)) in temps.into_iter().zip(files) {
        let target = dir.join(name);
        // On failure the error carries the temporary file, which its drop removes.
        temp.persist(&target).map_err(|e| e.error).with_context(|| format!("cannot write {}", target.display()))?;
    }
    remove_stale(dir, previous.difference(&now))?;
    write_manifest(dir, &now)?;
    sync_folder(dir);
    Ok(())
}

/// Whether `name` is a plain file name a build may write or remove: no path, and not hidden
/// (the manifest, the lock and temporary files are hidden, so no list can name them).
fn is_plain(name: &str) -> bool {
    !name.is_empty() && !name.starts_with('.') && !name.contains(['/', '\\'])
}

/// The pipeline names the files; a name that could leave the folder or clash with the
/// folder's own files, or a name given twice, is a bug, refused before anything is written.
fn check_names(files: &[(String, Vec<u8>)]) -> Result<()> {
    let mut seen = BTreeSet::new();
    for (name, _) in files {
        if !is_plain(name) || !seen.insert(name.as_str()) {
            bail!("cannot write an output named {name:?}: not a plain file name, or written twice");
        }
    }
    Ok(())
}

/// Locks the folder's lock file for as long as the returned file is open; when another build
/// holds it, says so once and waits.
fn lock_folder(dir: &Path) -> Result<File> {
    let file = open_lock_file(dir)?;
    let cannot = || format!("cannot lock {}", dir.join(LOCK).display());
    match file.try_lock() {
        Ok(()) => {}
        Err(TryLockError::WouldBlock) => {
            eprintln!("waiting for another build writing to {}…", dir.display());
            file.lock().with_context(cannot)?;
        }
        // A platform or file system without locks: build unguarded, as before locks existed.
        Err(TryLockError::Error(e)) if e.kind() == io::ErrorKind::Unsupported => {}
        Err(TryLockError::Error(e)) => return Err(e).with_context(cannot),
    }
    Ok(file)
}

/// Opens the lock file, creating it without following a symlink; an existing one must be a
/// regular file (a symlink planted there is refused rather than followed or replaced, since
/// replacing a lock file races with the builds that use it). Read access suffices to lock.
fn open_lock_file(dir: &Path) -> Result<File> {
    let path = dir.join(LOCK);
    match OpenOptions::new().write(true).create_new(true).open(&path) {
        Ok(file) => return Ok(file),
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
        Err(e) => return Err(e).with_context(|| format!("cannot create {}", path.display())),
    }
    let meta = fs::symlink_metadata(&path).with_context(|| format!("cannot read {}", path.display()))?;
    if !meta.is_file() {
        bail!("{} is not a regular file: remove it to let builds lock the folder", path.display());
    }
    File::open(&path).with_context(|| format!("cannot open {}", path.display()))
}

/// Removes the temporary files a killed build left (its process could not clean up: a
/// SIGKILL, a SIGXFSZ). Under the lock no other build is writing any. Best effort: a
/// leftover that cannot be removed harms nothing.
fn remove_leftover_temps(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let ours = name.to_str().is_some_and(|n| n.starts_with('.') && n.contains(TEMP_MARK));
        if ours && entry.file_type().is_ok_and(|t| t.is_file()) {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// The names the previous build wrote. Only a regular file is read (a planted symlink, FIFO
/// or device is ignored) and only plain names are trusted: a hand-edited manifest cannot make
/// a build delete anything outside the folder or the folder's own files.
fn read_manifest(dir: &Path) -> BTreeSet<String> {
    let path = dir.join(MANIFEST);
    if !fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
        return BTreeSet::new();
    }
    let mut text = String::new();
    let read = File::open(&path).and_then(|f| f.take(MANIFEST_LIMIT).read_to_string(&mut text));
    if read.is_err() {
        return BTreeSet::new();
    }
    text.lines().map(str::trim).filter(|n| is_plain(n)).map(str::to_string).collect()
}

/// One file written on its own, atomically (a temporary file beside it renamed into place),
/// outside any build's manifest: a report the user names.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<()> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().with_context(|| format!("{} names no file", path.display()))?;
    persist_synced(write_temp(dir, &name.to_string_lossy(), bytes)?, path)
}

/// Syncs `temp` to the disk and renames it to `path`: one file on its own.
fn persist_synced(temp: NamedTempFile, path: &Path) -> Result<()> {
    temp.as_file().sync_all().with_context(|| format!("cannot write {}", path.display()))?;
    temp.persist(path).map_err(|e| e.error).with_context(|| format!("cannot write {}", path.display()))?;
    Ok(())
}

/// Writes `bytes` to a new temporary file in `dir` named after `name`, not yet synced to
/// the disk (see [`sync_together`]): renamed into place only once synced, it cannot expose a
/// partial file after a crash.
fn write_temp(dir: &Path, name: &str, bytes: &[u8]) -> Result<NamedTempFile> {
    let prefix = format!(".{name}{TEMP_MARK}");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix);
    // tempfile's default mode is 0o600; outputs keep the mode a plain create gives them
    // (0o666 less the umask), as before they were written atomically.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let target = dir.join(name);
    let mut temp = builder.tempfile_in(dir).with_context(|| format!("cannot write {}", target.display()))?;
    temp.write_all(bytes).with_context(|| format!("cannot write {}", target.display()))?;
    Ok(temp)
}

/// Syncs the temporary files of `files` to the disk, all at once: each sync waits on the
/// disk (0.3 ms a file here, 9 ms for the worked example's 30 files one after another, a
/// tenth of its build), while syncs in flight together share the file system's commits.
fn sync_together(dir: &Path, temps: &[NamedTempFile], files: &[(String, Vec<u8>)]) -> Result<()> {
    std::thread::scope(|s| {
        let syncs: Vec<_> = temps.iter().map(|t| s.spawn(move || t.as_file().sync_all())).collect();
        syncs.into_iter().zip(files).try_for_each(|(sync, (name, _))| {
            let synced = sync.join().unwrap_or_else(|_| Err(io::Error::other("the sync's thread failed")));
            synced.with_context(|| format!("cannot write {}", dir.join(name).display()))
        })
    })
}

/// Records `names` as the manifest, atomically like every output.
fn write_manifest(dir: &Path, names: &BTreeSet<String>) -> Result<()> {
    let list: String = names.iter().map(|n| format!("{n}\n")).collect();
    let path = dir.join(MANIFEST);
    persist_synced(write_temp(dir, MANIFEST, list.as_bytes())?, &path)
}

/// Removes the previous build's `stale` files. Only regular files go: a symlink or folder now
/// at such a name was put there by someone else (removing a symlink would not follow it, but
/// it is not ours to remove).
fn remove_stale<'a>(dir: &Path, stale: impl Iterator<Item = &'a String>) -> Result<()> {
    for name in stale {
        let path: PathBuf = dir.join(name);
        if fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
            fs::remove_file(&path).with_context(|| format!("cannot remove the stale output {}", path.display()))?;
        }
    }
    Ok(())
}

/// Syncs the folder itself, which makes the renames durable (a file's sync does not cover
/// its name). Best effort and Unix only: the files are complete whatever happens here.
fn sync_folder(dir: &Path) {
    #[cfg(unix)]
    if let Ok(d) = File::open(dir) {
        let _ = d.sync_all();
    }
    #[cfg(not(unix))]
    let _ = dir;
}
