/* SPDX-License-Identifier: MIT */
/* A command's output folder, which never loses a file cablesim did not write.
 *
 * cs_out_open makes the folder, takes its lock (DIR/.cablesim-lock, made with O_EXCL, fcntl-locked, its text
 * "cablesim lock", the pid and the host: a second cablesim into the same folder is refused with that pid; a
 * lock whose holder has ended is removed and made anew; a file of that name with any other text is the
 * user's, kept, and the folder refused, even with CS_OUT_FORCE) and reads the manifest an earlier run left
 * (DIR/.cablesim-manifest: every file that run wrote, one a line with its size in bytes and the 64-bit FNV-1a
 * hash of its bytes; a file of that name that does not begin as cablesim's manifests do is the user's, kept,
 * and the folder refused, even with CS_OUT_FORCE). A listed file is cablesim's only while it is as written:
 * one changed since (its size or hash differs, or it is no longer a regular file), or listed without a size
 * and hash (a line typed in) or with them in another form than cablesim writes, is the user's. A folder
 * holding a file that is not cablesim's is refused, naming it, unless CS_OUT_FORCE: then the run writes
 * beside such files and touches none of them (nor writes over one).
 *
 * Each file is written to a unique temporary beside its name (mkstemp: ".cablesim-tmp.NAME.XXXXXX") and
 * flushed, its writing to the disk begun; cs_out_commit fsyncs them all, judges the folder again (a file
 * edited during the run is the user's then; one where a file goes fails the commit), renames them into place,
 * removes the files of the earlier manifest that this run did not write, and writes the new manifest last, by
 * a temporary and a rename: the commit point (the manifest written before the renames, which lists both runs'
 * files, is that one already when the earlier manifest named none). cs_out_abort removes the temporaries (and
 * the folders cs_out_open made) so a failed run leaves nothing. Either releases the lock. A sweep's journal,
 * beside them, is below.
 *
 * A signal (the command's handler of SIGINT and SIGTERM calls cs_out_signal_cleanup) does what
 * cs_out_abort does to every folder open, from within the handler: the folder is left as it was before
 * the command. Whatever changes the record of what a folder holds (a temporary made, a folder made, the
 * lock taken or released) does so with SIGINT and SIGTERM held back in its thread, so the handler never
 * finds a file made and not yet named; the commit holds them too from its first manifest on (its fsyncs of
 * the files before it do not), so a signal during a commit is taken once the files are in place: the
 * folder then holds the earlier run's files or this one's, never some of each. For this the handler must
 * run in the thread that writes the folder (a command's other threads block both signals). A kill -9
 * leaves the temporaries, which the next run into the folder removes, and the lock, which it takes over. */
#ifndef CS_OUTFILE_H
#define CS_OUTFILE_H

#include <stddef.h>
#include <stdio.h>

#include "cablesim/sim.h"

enum { CS_OUT_MAX_FILES = 64 }; /* the data files, the plots and the pages */
enum { CS_OUT_FORCE = 1 };      /* cs_out_open: write beside files no manifest lists */

#define CS_OUT_MANIFEST ".cablesim-manifest"
#define CS_OUT_LOCK ".cablesim-lock"
#define CS_OUT_TMP_PREFIX ".cablesim-tmp."
#define CS_OUT_JOURNAL ".cablesim-journal"
#define CS_OUT_JOURNAL_HEAD "{\"cablesim\":" /* how a journal's text begins: its study's record */

/* A file as cablesim wrote it: its size in bytes and the 64-bit FNV-1a hash of its bytes. */
typedef struct cs_out_print {
    long long size;
    unsigned long long hash;
} cs_out_print;

/* A line of the earlier manifest. ours 1: the file is as that run wrote it, or gone (2: removed by this run's
 * commit); 0: a file of that name
 * is there, changed since; -1: the line gives no size and hash in cablesim's form (typed in, or edited); -2:
 * another command wrote it (a sweep's results, met by a run), or one the manifest does not name (its "written
 * by" line edited). A file not ours is kept: the user's, or another command's results. */
typedef struct cs_out_listed {
    char name[128];
    cs_out_print print;
    int ours;
} cs_out_listed;

typedef struct cs_outdir {
    char dir[1024];
    int count;
    char names[CS_OUT_MAX_FILES][128];     /* the files begun, relative to dir */
    char tmps[CS_OUT_MAX_FILES][200];      /* their temporaries, relative to dir */
    int streams[CS_OUT_MAX_FILES][2];      /* their streams' descriptor and first write error (errno) */
    cs_out_print prints[CS_OUT_MAX_FILES]; /* the files' size and hash, taken at the commit */
    cs_out_listed *prev;                   /* the earlier run's manifest */
    int prev_count;
    int made;                    /* how many folders cs_out_open created */
    unsigned short made_at[128]; /* the lengths of the prefixes of dir naming them, in order */
    char subdirs[8][128]; /* the subfolders cs_out_subdir made (cs_out_abort removes them when empty) */
    int subdir_count;
    int flags;             /* CS_OUT_FORCE */
    char command[16];      /* the command writing ("run", "sweep", ...): the manifest's "written by" */
    char prev_command[16]; /* the earlier manifest's; "" if it names none, or two (another's results) */
    char aside[48]; /* the temporary of the manifest or the journal being written, relative to dir; "" */
    int lock;       /* the lock's file descriptor, -1 when not held */
    int in_place;   /* 1 once cs_out_commit has put the files in place (it may fail after that); -1 some of
                       them,   a failure it could not undo (its message says which) */
    int journal;    /* the journal's, open for appending; -1: none */
    unsigned mode;  /* the files' permissions: 0666 less the umask */
} cs_outdir;

/* Create dir (and its parents), take its lock and read its manifest, before anything is computed, for
 * the command (`cablesim COMMAND`: "run", "sweep", "validate", "compare", "designer") that writes it: the
 * files another command wrote there are that command's results, kept as the user's are. force names the
 * caller's way to CS_OUT_FORCE as its user gives it ("--force" on the command line, "the flag
 * CS_COMPARE_FORCE" in the library), which a refusal of the folder names; NULL: the caller has none.
 * Returns CS_OK, or CS_ERR_IO with err filled ("DIR: Not a directory", "DIR is in use by cablesim pid N",
 * "DIR holds notes.txt, which no cablesim run wrote there ...", or "... which has changed since cablesim
 * wrote it there ..."); CS_ERR_INVALID for a path too long, CS_ERR_MEMORY for a manifest that does not fit
 * in memory. Once it returned CS_OK, cs_out_commit or cs_out_abort ends out's use before out goes away
 * (cs_out_signal_cleanup reads it until then). */
cs_status cs_out_open(cs_outdir *out, const char *dir, const char *command, int flags, const char *force,
                      cs_error *err);
/* Create DIR/subdir, for files named "subdir/...". Returns CS_OK, or CS_ERR_IO with err filled. */
cs_status cs_out_subdir(cs_outdir *out, const char *subdir, cs_error *err);
/* Start a temporary for DIR/name. NULL with err filled on failure: CS_ERR_INVALID for a name longer than
 * names hold, CS_ERR_MEMORY past CS_OUT_MAX_FILES, CS_ERR_IO for a folder there, or a file no manifest lists
 * (CS_OUT_FORCE). */
FILE *cs_out_begin(cs_outdir *out, const char *name, cs_error *err);
/* Flush and close a file from cs_out_begin, its writing to the disk begun (cs_out_commit waits for it):
 * the last begun, or the i-th (files written side by side). Returns CS_OK, or CS_ERR_IO with err filled:
 * the file and the system's reason for its first failed write (a full disk: "No space left on device"). */
cs_status cs_out_end(cs_outdir *out, FILE *f, cs_error *err);
cs_status cs_out_end_at(cs_outdir *out, int i, FILE *f, cs_error *err);
/* End the last file begun (cs_out_end) after its writer returned status (not CS_OK: err holds its reason).
 * Returns CS_OK when both went well, else the file's own error when it had one (CS_ERR_IO, err saying which
 * file and the system's reason: "DIR/runs.csv: No space left on device"), else the writer's status with
 * err as the writer left it. */
cs_status cs_out_finish(cs_outdir *out, FILE *f, cs_status status, cs_error *err);
/* The same for a writer that opens its file by name (netCDF): the temporary's path into path (an empty
 * file the writer replaces), and, once the writer has closed it, cs_out_end_path begins its writing to the
 * disk. Each returns CS_OK, or a failure's status with err filled. */
cs_status cs_out_begin_path(cs_outdir *out, const char *name, char *path, size_t path_size, cs_error *err);
cs_status cs_out_end_path(cs_outdir *out, cs_error *err);
/* Fsync every temporary, judge the earlier files again (as cs_out_open did), rename each to its name, remove
 * the files of the earlier manifest that this run did not write (and a subfolder they leave empty), write the
 * manifest, release the lock. Returns CS_OK, or CS_ERR_IO with err filled (then call cs_out_fail). A name
 * that held no file when judged is renamed to only while it still holds none (RENAME_NOREPLACE): a file the
 * user saves there in that instant is kept, and fails the commit. A rename that fails takes back those done
 * before it (an earlier run's file replaced is kept until the commit ends, by RENAME_EXCHANGE), so the
 * folder holds the earlier run's results, whole; one it cannot take back stays, the commit saying so
 * (out->in_place -1): "DIR/events.csv: Operation not permitted; DIR holds this run's timeseries.csv, the rest
 * as before the command: run it again to write them all". The manifest lists both runs' files until the
 * renames are done, so it is true at every step and the next run owns either. An earlier
 * file that cannot be removed (a read-only folder) stays listed in the manifest, for the next run to remove,
 * and the commit ends, the new files in place (out->in_place), returning CS_ERR_IO: "the new results are in
 * DIR, but the earlier run's plots/speed.png could not be removed: Permission denied; ...". */
cs_status cs_out_commit(cs_outdir *out, cs_error *err);
/* After a failure while out was open (status, err its reason): cs_out_abort, and err's message begun with
 * "nothing written: " unless the commit had put files in place (its message then says which). Returns
 * status. err may be NULL. */
cs_status cs_out_fail(cs_outdir *out, cs_status status, cs_error *err);
/* A journal in the folder (DIR/.cablesim-journal, a sweep's: each run's result as it finishes), which
 * outlives a kill -9, a power cut or a failed write of the outputs, and which the commit of the sweep that
 * keeps it removes (the outputs hold it all then); to another command it is another command's results.
 * cs_out_journal_start writes its first text through a temporary, fsync and rename (it replaces an earlier
 * journal whole or not at all; a file of that name that does not begin with CS_OUT_JOURNAL_HEAD, as every
 * journal does, is the user's: kept, and the journal refused, even with CS_OUT_FORCE) and keeps it open;
 * cs_out_journal_add appends text and fsyncs. Each returns CS_OK, or CS_ERR_IO with err filled
 * ("DIR/.cablesim-journal: No space left on device"). */
cs_status cs_out_journal_start(cs_outdir *out, const char *text, size_t len, cs_error *err);
cs_status cs_out_journal_add(cs_outdir *out, const char *text, size_t len, cs_error *err);
/* The journal of the folder dir up to its last whole line (a line cut by a kill is dropped), malloc'ed and
 * NUL-terminated, its length in *len. NULL with err's status CS_OK: there is none; NULL with err filled
 * (CS_ERR_IO): it cannot be read. */
char *cs_out_journal_read(const char *dir, size_t *len, cs_error *err);
/* Remove the temporaries begun, and the folders cs_out_open made if they are empty; release the lock.
 * Safe to call twice, and after a commit (then it does nothing). */
void cs_out_abort(cs_outdir *out);
/* cs_out_abort's removals for every folder open in the process (from cs_out_open to cs_out_commit or
 * cs_out_abort; the first 8 open at once), for a handler of SIGINT or SIGTERM that then ends the process:
 * async-signal-safe (unlink, rmdir and memcpy on the paths each folder holds); it neither closes nor
 * frees anything. The lock's file is removed only while this process holds the lock. */
void cs_out_signal_cleanup(void);
/* A handler of SIGINT or SIGTERM: cs_out_signal_cleanup, then the process ends by the signal (its default
 * action, exit status 128 + the signal). */
void cs_out_end_by_signal(int sig);

#endif
