"""What the scripts that rewrite a COLMAP text model share: its rows and its quaternions."""
import math


def quat_to_matrix(w, x, y, z):
    """COLMAP's world -> camera quaternion (qw, qx, qy, qz) as a row-major 3x3 rotation."""
    n = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def rows(path):
    """The whitespace-split data lines of a COLMAP text file (comments and blank lines skipped)."""
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                yield line.split()
