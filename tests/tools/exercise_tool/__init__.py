"""The library behind tools/exercises.py (see its help)."""
