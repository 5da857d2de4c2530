"""Holder force varying in t (holder_force_varying.prm), with friction:
the holder must follow F(t) = 100 (1 + t + 0.5 sin 6t) N, which rises and
falls, at every increment; see holder_force_common for the tolerances."""
import math
import sys

from holder_force_common import check

if __name__ == "__main__":
    force = lambda t: 100.0 * (1.0 + t + 0.5 * math.sin(6.0 * t))
    sys.exit(1 if check(sys.argv[1], force) else 0)
