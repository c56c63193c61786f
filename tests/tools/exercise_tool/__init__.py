"""The library behind tests/tools/exercises.py (see its help)."""
