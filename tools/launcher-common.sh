# Sourced by tools/ff and tools/ff-mpi (not run): the checks both launchers make before FreeFEM
# starts, with the same messages (docs/errors.md), the removal of folders left by runs killed
# outright, and FreeFEM run as a child with its output filtered and the signals passed on. Each
# check stops the launcher (exit 3) naming the fix. No program is started where the shell itself
# does (each costs a run milliseconds).

# The launchers preload ROOT/plugin/build/fastclock.so and oomguard.so (LD_PRELOAD), whose list
# the loader splits at spaces and colons: in a checkout whose path holds a space it loaded neither
# (40 lines of "cannot be preloaded ... ignored"), and the run went on without its out-of-memory
# guard. There the libraries are named bare and found through LD_LIBRARY_PATH (split at colons and
# semicolons only); a path with a colon or a semicolon is refused (exit 3), naming it.
# require_preloadable ROOT: that refusal.
require_preloadable() {
  case "$1" in
    *[:\;]*)
      echo "error: the checkout's path '$1' holds a colon or a semicolon, which the loader's library lists cannot name (tools/ff preloads plugin/build/oomguard.so, its out-of-memory guard): clone or link the checkout to a path without them" >&2
      exit 3 ;;
  esac
}
# preload_entry ROOT LIB: sets $entry, LD_PRELOAD's name of ROOT/plugin/build/LIB (bare where ROOT
# holds a space, its folder then put first on LD_LIBRARY_PATH).
preload_entry() {
  case "$1" in
    *[[:space:]]*)
      entry=$2
      case ":${LD_LIBRARY_PATH:-}:" in
        *":$1/plugin/build:"*) ;;
        *) export LD_LIBRARY_PATH="$1/plugin/build${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ;;
      esac ;;
    *) entry="$1/plugin/build/$2" ;;
  esac
}

# require_umask: a umask that takes from the files' owner (umask 777, 0200) makes the run's own
# folders and files unusable to it: under umask 777 the launcher failed in its scratch folder
# ("cannot create .../pid: Permission denied", mkfifo), no error line. Refused (exit 3), naming it.
require_umask() {
  mask=$(umask)
  case "$mask" in
    0[0-7][0-7] | [0-7][0-7]) ;;  # (3 digits or fewer: the owner's digit is 0)
    00[0-7][0-7]) ;;
    *)
      echo "error: the umask $mask takes permissions from the files' owner: the run could not use the folders and files it makes; set one that leaves the owner rwx (umask 022, 077)" >&2
      exit 3 ;;
  esac
}

# require_sma_plugin ROOT: the SMA plugin ($SMA_PLUGIN, else ROOT/plugin/build/sma.so) built, a
# whole shared library, newer than its sources, of the scripts' version; sets $plugin and
# $plugin_dir (its folder, for FF_LOADPATH).
require_sma_plugin() {
  plugin="${SMA_PLUGIN:-$1/plugin/build/sma.so}"
  case "$plugin" in
    */sma.so) ;;
    *) echo "error: SMA_PLUGIN='$plugin' must name a file called sma.so (FreeFEM loads \"sma\")" >&2; exit 3 ;;
  esac
  if [ ! -f "$plugin" ]; then
    echo "error: the SMA plugin is not built ($plugin missing): run 'make plugin'" >&2
    exit 3
  fi
  # The version the scripts expect (edp/lib/plugin.idp), read here from the plugin's stamp
  # (plugin/glue/load.cpp): FreeFEM compiles a whole script before it runs any of it, so a plugin
  # lacking a function the scene calls stopped at compilation ("The Identifier ... does not
  # exist"), before plugin.idp's own check could speak.
  expected=""
  while IFS= read -r line; do
    case "$line" in
      *"SmaPluginVersion() == "[0-9]*) expected=${line#*SmaPluginVersion() == }; expected=${expected%%[!0-9]*} ;;
    esac
  done < "$1/edp/lib/plugin.idp"
  if [ -z "$expected" ]; then
    echo "error: $1/edp/lib/plugin.idp names no plugin version (its check 'SmaPluginVersion() == N')" >&2
    exit 3
  fi
  plugin_dir=${plugin%/*}  # (plugin ends in /sma.so: checked above)
  plugin_dir=${plugin_dir:-/}
  # readelf and the stamp's grep below read the whole plugin, two programs, 16 ms of the
  # launcher's 70: most runs of a test suite or a sweep start milliseconds apart on the same
  # plugin. A plugin that passed them gets a mark beside it, which holds while it is newer than
  # the plugin: a rebuild, a copy over it, a cut or any write makes the plugin newer and both
  # checks run again. (What it cannot see: a file moved into place, or copied with its time kept,
  # older than the mark; cut short, such a plugin still ends in the launcher's "a corrupt plugin"
  # line when FreeFEM dies loading it, and of another version in plugin.idp's own check.)
  verified="$plugin_dir/.sma.so.verified"
  mark=""
  if [ "$verified" -nt "$plugin" ]; then
    IFS= read -r mark < "$verified" 2>/dev/null
  fi
  checked=""
  [ "$mark" = "sma-plugin-version $expected verified" ] && checked=1
  # A plugin cut short or overwritten (a failed copy, a full disk during the build) would kill
  # FreeFEM with SIGBUS or SIGILL at load, without a word: readelf reads its section table, which
  # sits at the end of the file.
  # (readelf exits 0 on some damage and says so on stderr only: a failure or any complaint counts;
  # it runs without the user's LD_PRELOAD, whose missing library the loader complains of on stderr:
  # that complaint is the loader's about LD_PRELOAD, printed again as FreeFEM starts, not the plugin's.)
  if [ -z "$checked" ] && { ! complaint=$(LD_PRELOAD= readelf -S "$plugin" 2>&1 > /dev/null) || [ -n "$complaint" ]; }; then
    echo "error: the SMA plugin $plugin is not a valid shared library (corrupt or cut short): run 'make plugin'" >&2
    exit 3
  fi
  for src in "$1"/plugin/glue/*.cpp "$1"/plugin/glue/*.hpp "$1"/plugin/core/*.hpp; do
    if [ "$src" -nt "$plugin" ]; then
      echo "error: the SMA plugin is out of date ($src is newer than $plugin): run 'make plugin'" >&2
      exit 3
    fi
  done
  # FreeFEM reads ./freefem++.pref (make writes one here, naming plugin/build) before FF_LOADPATH:
  # from such a directory the override would silently load the real plugin.
  if [ -n "$SMA_PLUGIN" ] && [ -f freefem++.pref ] && grep -q loadpath freefem++.pref; then
    echo "error: SMA_PLUGIN cannot take effect here: ./freefem++.pref puts its own plugin path first; run from another directory" >&2
    exit 3
  fi
  [ -z "$checked" ] || return 0
  stamp=$(grep -a -o -m 1 'sma-plugin-version [0-9]*;' "$plugin")
  stamp=${stamp#sma-plugin-version }
  stamp=${stamp%;}
  if [ -z "$stamp" ]; then
    echo "error: the SMA plugin $plugin has no version stamp (not this suite's, or built before the stamp): run 'make plugin'" >&2
    exit 3
  fi
  if [ "$stamp" != "$expected" ]; then
    echo "error: the SMA plugin $plugin has version $stamp, the scripts expect $expected (edp/lib/plugin.idp): run 'make plugin'" >&2
    exit 3
  fi
  # (a folder this user cannot write in keeps no mark: its runs check every time)
  { printf 'sma-plugin-version %s verified\n' "$expected" > "$verified"; } 2>/dev/null || :
}

# require_built ROOT NAME SOURCE [HINT]: ROOT/plugin/build/NAME built from ROOT/SOURCE and not
# older than it; HINT adds to the message.
require_built() {
  if [ ! -f "$1/plugin/build/$2" ] || [ "$1/$3" -nt "$1/plugin/build/$2" ]; then
    echo "error: $1/plugin/build/$2 is missing or older than $3: run 'make plugin'$4" >&2
    exit 3
  fi
}

# remove_stale_folders PREFIX: a launcher killed outright (KILL, which no trap sees: a job
# manager's hard stop) leaves its temporary folder ${TMPDIR:-/tmp}/PREFIX.*; each run first
# removes those whose owner (the pid written in them) is gone.
remove_stale_folders() {
  for stale in "${TMPDIR:-/tmp}/$1".*/pid; do
    [ -f "$stale" ] || continue
    owner=""
    IFS= read -r owner < "$stale" 2>/dev/null
    case "$owner" in ''|*[!0-9]*) continue ;; esac
    [ -d "/proc/$owner" ] || rm -rf "${stale%/pid}" 2>/dev/null
  done
}

# require_open_files N WHY: the open-file limit at least N, else a stop (exit 3) saying WHY N are
# needed (with 12, tools/ff's shell itself ran out of descriptors: "tools/ff: 20: .: 3: Too many
# open files", exit 2 and no error line; with 32 Open MPI stopped for want of pipes).
require_open_files() {
  files=$(ulimit -n 2>/dev/null)
  case "$files" in
    ''|unlimited) ;;
    *) if [ "$files" -lt "$1" ]; then
         echo "error: the open-file limit (ulimit -n $files) is below $1: $2: raise it (ulimit -n 1024)" >&2
         exit 3
       fi ;;
  esac
}

# scratch_failed: the stop (exit 3) when mktemp could not make the launcher's temporary folder
# (TMPDIR=/sys gave only mktemp's own line and exit 3).
scratch_failed() {
  echo "error: no scratch folder could be made in ${TMPDIR:-/tmp} (\$TMPDIR, else /tmp; mktemp's line above says why): set TMPDIR to a writable folder" >&2
  exit 3
}

# require_tmpdir: $TMPDIR, where the launcher makes its temporary folder (and the plugin its
# scratch folders), an existing directory when set; a relative one made absolute (the plugin
# follows only an absolute TMPDIR) and exported.
require_tmpdir() {
  [ -n "$TMPDIR" ] || return 0
  if [ ! -d "$TMPDIR" ] || [ ! -w "$TMPDIR" ]; then
    echo "error: TMPDIR='$TMPDIR' is not a directory this run can write in (the launcher's temporary folder goes there): create it, or unset TMPDIR" >&2
    exit 3
  fi
  case "$TMPDIR" in
    /*) ;;
    *) TMPDIR=$(cd -- "$TMPDIR" && pwd) || exit 3 ;;
  esac
  export TMPDIR
}

# FreeFEM's output without the call trace it prints after a script's own exit: exit(1) after an
# `error:` line, exit(0) (-help, -checkonly) or exit(4) after a sleeve run's "stopped after step N"
# (-stopafter): "  current line = N", " call F  at  line N", "exit(N)", " err code N ,  mpirank 0",
# six lines after every error that said nothing the error line does not. After any other exit (an
# execution error, an internal one) the trace is kept: it says where. (FreeFem++-mpi's first line
# reads "  current line = N mpirank R / S".) With SMA_SAID naming a file, the error lines also go
# there (tools/ff-mpi's record of what rank 0 said).
untraced='
  BEGIN { said = ENVIRON["SMA_SAID"] }
  function trailer(line) {
    return line ~ /^  current line = [0-9]+( mpirank [0-9]+ \/ [0-9]+)?$/ || line ~ /^ call .* at  line [0-9]+$/ \
      || line ~ /^exit\([0-9]+\)$/ || line ~ /^ err code [0-9]+ ,  mpirank [0-9]+$/
  }
  { if (trailer($0)) { held[++n] = $0; next }
    for (i = 1; i <= n; i++) print held[i]
    n = 0
    # (an error line on standard error, as the launchers print theirs: FreeFEM prints the cerr of
    # a script on its standard output, and a run with its output sent away or closed lost the line)
    if ($0 ~ /^error: /) { fflush(); print > "/dev/stderr"; fflush("/dev/stderr") } else print
    if (said != "" && $0 ~ /^error: /) { print >> said; fflush(said) }
    fflush() }
  END { clean = 0
    for (i = 1; i <= n; i++) if (held[i] ~ /^ err code [014] ,/) clean = 1
    if (!clean) for (i = 1; i <= n; i++) print held[i] }'

# The filter reads a line at a time: mawk, Debian's awk, fills its input buffer before it hands a
# line on, so a run's progress lines (one every 5 s) reached the terminal in bursts, or all at the
# run's end: a run that looked hung (tests/progress_test.py). -W interactive makes its reads
# line-buffered; gawk reads what has come.
# (mawk by name where it is installed, found by the shell itself: asking awk its version took
# three programs, 27 ms of processor time, at every run)
if command -v mawk > /dev/null 2>&1; then
  line_awk="mawk -W interactive"
else
  line_awk="awk"
fi

# published_since MARKER ARGS...: sets $published to the run's results folder (its -out among ARGS,
# else results/<the script's name>) when the run completed there after MARKER was made (its
# summary.json newer, the folder's mark of completion there), else "". A signal that arrives as a
# run ends, after it published its results, was said to have left "nothing published ... continues
# with -resume 1", while the results were whole and the checkpoint gone (a window of about 10 ms,
# 70-110 ms on MPI ranks).
published_since() {
  marker=$1
  shift
  out=""
  name=""
  previous=""
  for word in "$@"; do
    [ "$previous" = "-out" ] && out=$word
    case "$word" in
      *.edp) name=${word##*/}; name=${name%.edp} ;;
    esac
    previous=$word
  done
  [ -n "$out" ] || out="results/$name"
  published=""
  if [ -f "$out/.sma-complete" ] && [ "$out/summary.json" -nt "$marker" ]; then published=$out; fi
}

# run_filtered FIFO COMMAND...: COMMAND as a child this shell waits for, its standard input this
# script's (an asynchronous command's would be /dev/null), its standard output through the filter
# $untraced by way of the FIFO made at FIFO (so that $child is COMMAND itself). A TERM, INT or HUP
# to the launcher is passed on as a TERM (and sets $stopped to 128 + its number); the filter ignores them (it ends when
# the output does: a Ctrl-C stops the run, not the messages on their way). Sets $rc, the child's
# exit code.
# The trap is set before the child starts: a signal between the start and `child=$!` found no trap
# and killed the launcher, while the child, still in setpriv with INT ignored (an asynchronous
# child's), set its parent-death signal too late and ran on to publish. The launcher holds the FIFO
# open (fd 4, read-write: Linux opens it at once) until the child has ended, so that the filter's
# open never waits for the child's: a child stopped before it opened its output never made it, and
# the filter, with the launcher waiting for it, hung for ever (tests/signals_test.py, a sweep's run
# stopped as it started: 2 failures in 6 runs, 0 in 8 since).
run_filtered() {
  fifo=$1
  shift
  mkfifo "$fifo"
  exec 4<>"$fifo"
  # (the filter drains the FIFO to its end even when its own output fails: a reader that went away,
  # `| head -1`, or a closed standard output killed awk, and the run, its output no longer read,
  # blocked for ever once the FIFO's 64 KB were full)
  env --ignore-signal=INT,TERM,HUP,QUIT sh -c "$line_awk \"\$1\"; exec cat > /dev/null" filter "$untraced" \
    < "$fifo" 4>&- &
  filter=$!
  child=""
  stopped=""
  # ($stopped: 128 + the signal's number, so that the run is said stopped by the one it got and
  # exits with it: an INT was reported as "died of signal SIGTERM (exit 143)")
  trap 'stopped=143; [ -z "$child" ] || kill -TERM "$child" 2>/dev/null' TERM
  trap 'stopped=130; [ -z "$child" ] || kill -TERM "$child" 2>/dev/null' INT
  trap 'stopped=129; [ -z "$child" ] || kill -TERM "$child" 2>/dev/null' HUP
  # (a closed standard input is /dev/null to the child: `exec 3<&0` on it stopped the launcher
  # with "Bad file descriptor", exit 2, no error line)
  if [ -e /dev/fd/0 ]; then exec 3<&0; else exec 3</dev/null; fi
  "$@" <&3 3<&- 4>&- > "$fifo" &
  child=$!
  exec 3<&-
  [ -z "$stopped" ] || kill -TERM "$child" 2>/dev/null
  rc=0
  wait "$child" || rc=$?
  # wait returns early (rc > 128) when a trapped signal arrives: wait again until the child has ended
  while kill -0 "$child" 2>/dev/null; do
    rc=0
    wait "$child" || rc=$?
  done
  trap - TERM INT HUP
  exec 4>&-  # (the filter reads to the end now that the child's output is closed)
  wait "$filter" 2>/dev/null  # its last lines out before ours
}
