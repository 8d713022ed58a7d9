#!/bin/sh
# Start script for raytracer, written by `gradle installDist` from src/launcher/raytracer.sh.
# It does what Gradle's generated script does on Linux and macOS, without the process starts that
# script makes on every launch (uname, basename, which, ulimit, a sed per argument), about 20 ms
# that a short render waits for (docs/performance.md, "Start-up").
#   JAVA_HOME                  the Java installation to use (else `java` on the PATH)
#   JAVA_OPTS, RAYTRACER_OPTS  more JVM options (shell quoting honoured, as in Gradle's scripts)
#   RAYTRACER_NO_CDS=1         start without the class-data-sharing archive
#   RAYTRACER_JIT=short|long   the JIT: short = C1 only (DEFAULT_JVM_OPTS), long = full tiered
#                              compilation (C2); unset: C1, and the program starts this script again
#                              with RAYTRACER_JIT=long when the render plan says the render is long
#                              (docs/performance.md, "The JIT policy"); JVM options naming the JIT
#                              in JAVA_OPTS or RAYTRACER_OPTS are left alone
#   CLASSPATH                  more class path (a student's compiled classes), after the installation's
# and one option of its own, anywhere before `--`: --class-path PATH (also -cp PATH, --class-path=PATH),
# the same as CLASSPATH; the renderer's other options pass through unchanged.

# The installation: follow symbolic links to this script; its directory's parent.
app_path=$0
while [ -h "$app_path" ]; do
    ls=$(ls -ld -- "$app_path")
    link=${ls#*' -> '}
    case $link in
        /*) app_path=$link ;;
        *) app_path=${app_path%/*}/$link ;;
    esac
done
case $app_path in
    */*) app_dir=${app_path%/*} ;;
    *) app_dir=. ;;
esac
saved_pwd=$PWD
cd -P -- "$app_dir/.." || exit 1
APP_HOME=$PWD
cd -- "$saved_pwd" || exit 1

if [ -n "$JAVA_HOME" ]; then
    JAVACMD=$JAVA_HOME/bin/java
    if [ ! -x "$JAVACMD" ]; then
        echo "ERROR: JAVA_HOME is set to an invalid directory: $JAVA_HOME" >&2
        exit 1
    fi
else
    JAVACMD=java
fi

user_cp=${CLASSPATH-}
app_cp=@CLASSPATH@

# --class-path / -cp PATH: taken out of the arguments (the rest keep their order), added with $CLASSPATH
# after the installation's own class path, so a student's classes are found by the scene parser (a
# class of the same name as one of the renderer's is not replaced). No process start, nothing eval'd.
n=$#
while [ "$n" -gt 0 ]; do
    a=$1
    shift
    n=$((n - 1))
    case $a in
        --)
            set -- "$@" "$a"
            while [ "$n" -gt 0 ]; do set -- "$@" "$1"; shift; n=$((n - 1)); done ;;
        -cp|--class-path|--classpath)
            if [ "$n" -eq 0 ]; then
                echo "raytracer: $a needs a class path (folders or jars, ':'-separated; see --help)" >&2
                exit 2
            fi
            user_cp=${user_cp:+$user_cp:}$1
            shift
            n=$((n - 1)) ;;
        --class-path=*|--classpath=*|-cp=*)
            user_cp=${user_cp:+$user_cp:}${a#*=} ;;
        *)
            set -- "$@" "$a" ;;
    esac
done
if [ -n "$user_cp" ]; then
    app_cp=$app_cp:$user_cp
    # exported as CLASSPATH (which java ignores beside -classpath), so a start of this script again by the
    # program (the JIT policy's RAYTRACER_RELAUNCH, with the options it was given) finds the same classes
    CLASSPATH=$user_cp
    export CLASSPATH
fi
DEFAULT_JVM_OPTS=@DEFAULT_JVM_OPTS@

# An argument whose bytes are not UTF-8 (a file name in Latin-1, say) reaches the JVM as U+FFFD, so no
# file of that name can be opened or written: say so in one line, with the way round it, before the JVM
# starts. Only an argument with a byte outside printable ASCII costs a process (iconv) to check.
for a do
    case $a in
        *[!\ -~]*)
            if command -v iconv >/dev/null 2>&1 && ! printf '%s' "$a" | iconv -f UTF-8 -t UTF-8 >/dev/null 2>&1; then
                shown=$(printf '%s' "$a" | LC_ALL=C tr -c '[:print:]' '?')
                echo "raytracer: the name '$shown' is not valid UTF-8 (a name in another encoding, e.g. Latin-1), and Java cannot open a file by such a name: rename the file (e.g. convmv -f latin1 -t utf8), or give it by redirection: raytracer - < NAME reads a scene, raytracer -o - scene.txt > NAME writes an image" >&2
                exit 2
            fi ;;
    esac
done

# Whether stderr and stdout are terminals (the progress bar goes to stderr only when it is one; Java's
# System.console() asks about stdin and stdout together). `[` is a shell builtin: no process start.
if [ -t 2 ]; then tty2=true; else tty2=false; fi
# (a long render started by the JIT policy through a pipe that filters its stderr: the first process's answer)
case ${RAYTRACER_STDERR_TTY-} in true|false) tty2=$RAYTRACER_STDERR_TTY ;; esac
if [ -t 1 ]; then tty1=true; else tty1=false; fi

# The java command line, built last argument first. Nothing taken from a path (the installation's
# folder, the class path) ever passes through `eval`: an installation under a folder named
# x$(touch PWNED)y or a"b starts like any other (the launcher test installs under such names).
set -- -classpath "$app_cp" @MAIN@ "$@"
set -- "-Draytracer.stderrTty=$tty2" "-Draytracer.stdoutTty=$tty1" "$@"

# JAVA_OPTS and RAYTRACER_OPTS: split as Gradle's own script splits them (xargs honours quotes), then
# every character that is not plainly safe is escaped, so no `$`, backquote or `;` in them runs
# anything. Only when set: the common start makes no extra process.
if [ -n "$JAVA_OPTS$RAYTRACER_OPTS" ]; then
    user_opts=$(printf '%s\n' "$JAVA_OPTS $RAYTRACER_OPTS" | xargs -n1 | sed 's~[^-[:alnum:]+,./:=@_]~\\&~g' | tr '\n' ' ') || exit 1
    eval "set -- $user_opts \"\$@\""
fi

# The JIT policy (ray.app.JitPolicy): C1 only (DEFAULT_JVM_OPTS) unless RAYTRACER_JIT=long, whose
# full tiered compilation comes after the build's options and before the user's. Unset, the program may
# start this script again, by this path (an environment variable: never read by the shell again), with
# RAYTRACER_JIT=long when its render plan says the render is long, unless the user's options chose a JIT.
# Long: at least four compiler threads (the JVM gives 2 CPUs two, one of them C2's, and 8 CPUs four). A
# long render's hottest methods are recompiled several times as rare branches and types turn up, and
# while a compilation waits in one C2 thread's queue every render thread runs the slower profiled code:
# classichd 0.93x, mesh1m 0.94x the CPU time (docs/performance.md, "Long renders: the JIT's warm-up").
# Raised only where the online CPU count (one getconf, long renders only) is below 8; a user's
# -XX:CICompilerCount comes later and wins. A long render also renders a few pixels spread over the image
# before its tiles (-Dray.render.warmUp=true, ray.render.Renderer.WARM_UP), so that the profiles C2 compiles
# from are the whole image's, not its first tiles': fewer of those recompilations (classichd 0.95x the CPU).
# Long: the BVH's build is never compiled by C2 (lib/c2-directives.json, a HotSpot compiler-directives file:
# no C2 for ray.accel.BvhBuilder and its nested classes, the Bvh constructor's layout of the tree and
# Wide4.collapse; JSON without comments, which the JVM's reader refuses before the array). It runs once, and
# C2's code for it came too late to pay: on mesh1m C2 spent about 0.3 s compiling it, the build took as
# long either way, and C2's threads were busy while the render's own methods waited (mesh1m 0.95x the CPU
# time, docs/performance.md, "Issue 20, session 36"). The builder runs C1's code without profiling instead.
# Diagnostic options, unlocked for that; the JVM prints "1 compiler directives added" on starting, and so
# that it never lands in an image written to stdout (-o -) all of the JVM's own output goes to stderr,
# where the JIT policy's relaunch drops that line. A user's later -XX:CompilerDirectivesFile wins.
case ${RAYTRACER_JIT-} in
    long)
        case $(getconf _NPROCESSORS_ONLN 2>/dev/null) in
            [1-7]) set -- -XX:CICompilerCount=4 "$@" ;;
        esac
        if [ -f "$APP_HOME/lib/c2-directives.json" ]; then
            set -- -XX:+UnlockDiagnosticVMOptions -XX:+DisplayVMOutputToStderr \
                "-XX:CompilerDirectivesFile=$APP_HOME/lib/c2-directives.json" "$@"
        fi
        set -- -XX:TieredStopAtLevel=4 -Dray.render.warmUp=true "$@" ;;
    short) ;;
    *)
        case " $JAVA_OPTS $RAYTRACER_OPTS " in
            *Tiered*|*-Xint*|*-Xcomp*|*-XX:CompilationMode*) ;;
            *) RAYTRACER_RELAUNCH=$APP_HOME/bin/${app_path##*/}; export RAYTRACER_RELAUNCH ;;
        esac ;;
esac

# Class-data sharing (docs/performance.md): skipped when missing, ignored by the JVM when stale. The
# archive's path is one quoted argument, never read again by the shell.
if [ -f "$APP_HOME/lib/raytracer.jsa" ] && [ -z "$RAYTRACER_NO_CDS" ]; then
    set -- "-XX:SharedArchiveFile=$APP_HOME/lib/raytracer.jsa" "-Xlog:cds*=off" "$@"
fi

# File names: the JVM decodes arguments and file names in the locale's character set, which under
# LC_ALL=C (cron, containers) is ASCII, so `raytracer café.txt` became 'caf??.txt'. Where the locale's
# set is not UTF-8, the JVM gets C.UTF-8 (a shell builtin case: no process start).
case "${LC_ALL:-${LC_CTYPE:-$LANG}}" in
    *[Uu][Tt][Ff]-8*|*[Uu][Tt][Ff]8*) ;;
    *) LC_ALL=C.UTF-8; export LC_ALL ;;
esac

# A long render with RAYTRACER_SIMD=1 (the JIT policy sets it for a large scene where the JDK has the
# module, on JDK 17-25) traverses its tree four boxes at a time through the JDK's Vector API (ray.accel.Wide4; mesh1m
# 0.90-0.94x the CPU time, docs/performance.md, "A 4-wide BVH in SIMD"). The API is an incubator module in JDK
# 17-25, which the JVM announces on stderr at every start; the JIT policy, which started this script, drops
# that line (and tells whether its own stderr is a terminal: RAYTRACER_STDERR_TTY, above). Wide4's box test
# (enter, planes) is inlined whatever C2's size heuristics say: a vector passed to a call that is not inlined
# is an object on the heap (mesh1m's peak RSS was 2 GiB without it). Its three traversals (*Hit*) are never
# inlined into their callers in Bvh, so C2 compiles each once, on its own: inlined, they were compiled twice,
# in Bvh's method and alone (with the unsorted any hit, mesh1m 0.91-0.94x the CPU time; docs/performance.md,
# "The JIT's share of a long render").
# Until C2 has compiled the wide traversal its vectors are objects, a burst of garbage for which the parallel
# collector grew the young generation to hundreds of MiB (mesh1m's peak RSS 640-1100 MiB). Capped at 192 MiB
# it is collected in a few more short pauses at the same CPU time (mesh100k at 48 M camera rays 0.99x; a
# fixed -Xmn96m cost it 1.03-1.07x), peak RSS about 460 and 380 MiB. A cap, not a size (-Xmn): the old
# generation keeps the rest of a small heap. Not when the user's options size the heap themselves; a heap of
# 192 MiB or less (a machine of 768 MiB) gets the JVM's warning that the cap is the whole heap.
if [ "${RAYTRACER_JIT-}" = long ] && [ "${RAYTRACER_SIMD-}" = 1 ]; then
    case " $JAVA_OPTS $RAYTRACER_OPTS " in
        *-Xm[xns]*|*NewSize*|*NewRatio*|*HeapSize*) ;;
        *) set -- -XX:MaxNewSize=192m "$@" ;;
    esac
    set -- --add-modules=jdk.incubator.vector -Dray.bvh.wide=true -XX:CompileCommand=inline,ray.accel.Wide4::enter \
        -XX:CompileCommand=inline,ray.accel.Wide4::planes -XX:CompileCommand=inline,ray.accel.Wide4::sortEntered \
        "-XX:CompileCommand=dontinline,ray.accel.Wide4::*Hit*" "$@"   # quoted: a glob
fi

# The build's own JVM options: a constant the build writes here (quoted words, no path in it).
eval "set -- $DEFAULT_JVM_OPTS \"\$@\""
exec "$JAVACMD" "$@"
