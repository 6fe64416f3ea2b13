"""Reads the spectral CSV tables of spectra/data (and scene CSVs): '#' comment lines, one header line,
then numbers; the first column is the wavelength in nm. numpy only (for the scripts in tools/data/)."""
import numpy as np


def read_table(path):
    """Returns (header names, 2-D float array of the rows)."""
    with open(path) as f:
        lines = [line.strip() for line in f if line.strip() and not line.lstrip().startswith("#")]
    header = [name.strip() for name in lines[0].split(",")]
    rows = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    return header, rows


def read_columns(path):
    """Returns {column name: values} including the wavelength column under its own name."""
    header, rows = read_table(path)
    return {name: rows[:, i] for i, name in enumerate(header)}
