"""Shared helpers of the recording scripts: recordings through collidescope.open.

collidescope.open (python/collidescope/recording.py) is pure Python on h5py and numpy, so the
scripts need nothing built: they use an importable `collidescope` package when there is one
(PYTHONPATH=build/python, or installed), and this repository's python/ otherwise.
"""
import os
import sys

try:
    import collidescope
except ImportError:
    sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
    import collidescope


def open_recording(path):
    """Opens PATH (SWMR, so a recording being written or killed opens too); exits with one
    line naming the file when it is not a readable recording."""
    try:
        return collidescope.open(path)
    except collidescope.RecordingError as error:
        sys.exit(str(error))
