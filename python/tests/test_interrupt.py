# Long calls release the GIL and stop on Ctrl-C: a SIGINT while a Gröbner basis or a render
# runs raises KeyboardInterrupt promptly (the issue asks for 0.2 s; the bound here leaves room
# for a loaded machine, and the measured latency is printed).
import os
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import locus

SCRIPT = textwrap.dedent("""
    import os, signal, sys, threading, time
    import locus
    which, source = sys.argv[1], sys.argv[2]
    fired = []
    def fire():
        fired.append(time.time())
        os.kill(os.getpid(), signal.SIGINT)
    threading.Timer(0.4, fire).start()
    try:
        if which == "groebner":
            locus.groebner(locus.read_ideal(source + "/bench/data/cyclic7.ideal"),
                           algorithm="buchberger")
        elif which == "modular":
            locus.groebner(locus.read_ideal(source + "/bench/data/katsura10.ideal"),
                           algorithm="modular")
        else:
            locus.render("x^30+y^30+z^30-1+(x*y*z)^10", size=(2048, 2048))
        print("finished")
    except KeyboardInterrupt:
        print("interrupted %.3f" % (time.time() - fired[0]))
""")


@pytest.mark.parametrize("which", ["groebner", "modular", "render"])
def test_ctrl_c_stops_the_work(source_dir, which):
    result = subprocess.run([sys.executable, "-c", SCRIPT, which, str(source_dir)],
                            capture_output=True, text=True, timeout=120,
                            env=dict(os.environ))
    words = result.stdout.split()
    assert words and words[0] == "interrupted", result.stdout + result.stderr
    latency = float(words[1])
    print("%s: KeyboardInterrupt %.3f s after SIGINT" % (which, latency))
    assert latency < 1.0


def test_the_gil_is_released(source_dir):
    # katsura-8 by Buchberger: about 0.2 s, long enough for the other thread to tick.
    ideal = locus.read_ideal(str(source_dir / "bench/data/katsura8.ideal"))
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.time())
            time.sleep(0.005)

    thread = threading.Thread(target=tick)
    thread.start()
    start = time.time()
    locus.groebner(ideal, algorithm="buchberger")
    elapsed = time.time() - start
    stop.set()
    thread.join()
    # Python ran beside the computation: ticks spread over it, not only after it.
    during = [t for t in ticks if start < t < start + elapsed]
    assert len(during) >= 3, "%d ticks in %.3f s" % (len(during), elapsed)


OTHER_THREAD = textwrap.dedent("""
    import os, signal, sys, threading, time
    import locus
    source = sys.argv[1]
    other = {}
    def work():
        try:
            for _ in range(3):
                locus.groebner(locus.read_ideal(source + "/bench/data/katsura9.ideal"))
            other["result"] = "done"
        except Exception as e:
            other["result"] = type(e).__name__
    helper = threading.Thread(target=work)
    helper.start()
    threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    try:
        locus.groebner(locus.read_ideal(source + "/bench/data/cyclic7.ideal"),
                       algorithm="buchberger")
        print("main finished")
    except KeyboardInterrupt:
        print("main interrupted")
    helper.join()
    print("other", other["result"])
""")


def test_ctrl_c_stops_only_the_main_threads_call(source_dir):
    # Each call's deadline is its own cancellable one (algebra/deadline.h): Ctrl-C stops the
    # main thread's call, and a call in another thread runs to its end.
    result = subprocess.run([sys.executable, "-c", OTHER_THREAD, str(source_dir)],
                            capture_output=True, text=True, timeout=120, env=dict(os.environ))
    lines = result.stdout.split("\n")
    assert "main interrupted" in lines, result.stdout + result.stderr
    assert "other done" in lines, result.stdout + result.stderr


def test_repeated_calls_do_not_leak_the_worker_threads_memory(source_dir):
    # Each long call runs on a thread of its own, and FLINT's caches are per thread: without
    # releasing them when the thread ends, every call that met big integers left about 220 kB
    # behind (katsura7: 6.6 MB over 30 calls). Resident memory now, not the peak (a child
    # forked from pytest starts with pytest's peak).
    script = textwrap.dedent("""
        import sys
        import locus
        def resident_kb():
            for line in open("/proc/self/status"):
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
        ideal = locus.read_ideal(sys.argv[1] + "/bench/data/katsura7.ideal")
        for algorithm in ("buchberger", "auto"):
            locus.groebner(ideal, algorithm=algorithm)
        before = resident_kb()
        for i in range(30):
            locus.groebner(ideal, algorithm="buchberger" if i % 2 else "auto")
        print(resident_kb() - before)
    """)
    out = subprocess.run([sys.executable, "-c", script, str(source_dir)], capture_output=True,
                         text=True, timeout=120, env=os.environ)
    assert out.returncode == 0, out.stderr
    growth_kb = int(out.stdout.strip())
    print("resident memory growth over 30 calls: %d kB" % growth_kb)
    assert growth_kb < 2048
