"""A long Python process does not leak: 1,000 renders (and lines) in one session, and sessions
opened and closed, leave the resident size within a few MB of where it settled.

These run with the validation layer off: its synchronization validation keeps ~19 KB of access
history per frame submitted (measured: +17 MB over 800 frames with it, +0.0 MB with the core
checks alone or without the layer), which is the layer's memory, not the module's."""
import gc

import linework
from conftest import SOURCE


def resident_mb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    raise AssertionError("no VmRSS in /proc/self/status")


def growth_mb(step, rounds):
    """Resident growth over `rounds` calls of step(). A leak grows in every such window; a one-off
    jump (glibc opening another arena when threads contend on a loaded machine) does not, so a
    window over the limit is measured again, up to three windows in all, and any one under the
    limit decides. Such jumps are common (the 30-session window: +5.1 MB then +0.27 MB in one run
    of five beside a SLAM synthesis, +5.0 then +0.6 MB in a run alone); this test failed one
    full run of the suite on 2026-12-04 (its output was lost), as two jumps in a row would. A
    step that keeps 200 KB a call still fails: +5.7, +5.9, +5.9 MB."""
    before = resident_mb()
    for i in range(rounds):
        step(i)
    gc.collect()
    return resident_mb() - before


def assert_flat(step, rounds, what, limit=4.0, windows=3):
    grown = []
    for _ in range(windows):
        grown.append(growth_mb(step, rounds))
        print(f"+{grown[-1]:.2f} MB after {what}")
        if grown[-1] < limit:
            return
    assert False, f"grew in every one of {windows} windows of {what}: " + ", ".join(f"+{g:.2f} MB" for g in grown)


def test_a_thousand_renders_do_not_grow_the_process():
    s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=(96, 72), validation=False)
    for _ in range(50):  # the allocator's and lavapipe's pools settle
        s.render()
        s.lines()

    def step(i):
        s.render()
        if i % 5 == 0:
            s.lines()

    assert_flat(step, 1000, "1000 renders and 200 lines()")


def test_sessions_opened_and_closed_do_not_accumulate():
    def cycle():
        s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=(64, 48), validation=False)
        s.render()
        del s
        gc.collect()

    for _ in range(25):  # glibc keeps freed memory (core/memory.h): the heap settles in ~25 cycles
        cycle()
    assert_flat(lambda i: cycle(), 30, "30 sessions")
