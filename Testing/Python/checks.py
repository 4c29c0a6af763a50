"""The Python tests' checks: each prints "ok   ..." or "FAIL ..." (ctest fails on the
latter), and finish() prints the count and exits 1 when any failed."""
import sys

failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)
    return condition


def finish():
    print(f"{len(failures)} failure(s)")
    sys.exit(1 if failures else 0)
