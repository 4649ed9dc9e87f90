"""CSV files of runs, one row per configuration, keyed by the column 'key'.

Files are always written whole: to NAME.tmp, then renamed over NAME.
"""
import csv
import os


def read_rows(path):
    """Rows of a CSV file as dicts, or [] if it does not exist."""
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def columns_of(rows, first=()):
    """Every column of the rows: the 'first' ones in order, then the others as they appear."""
    columns = [c for c in first]
    for row in rows:
        for c in row:
            if c not in columns:
                columns.append(c)
    return columns


def write_whole(path, text):
    """Writes text to path whole (tmp file + rename), making its folder."""
    tmp = path + ".tmp"
    directory = os.path.dirname(path)
    if directory:
        os.makedirs(directory, exist_ok=True)
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def write_rows(path, rows, first=("key",)):
    """Writes rows whole (tmp file + rename); missing cells are empty."""
    tmp = path + ".tmp"
    directory = os.path.dirname(path)
    if directory:
        os.makedirs(directory, exist_ok=True)
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns_of(rows, first), restval="")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    os.replace(tmp, path)


def merge(paths):
    """Rows of several CSV files (shards), one per key; the same key twice must hold the same result."""
    by_key = {}
    for path in paths:
        if not os.path.exists(path):
            raise SystemExit(f"merge: {path} does not exist")
        for row in read_rows(path):
            key = row.get("key")
            if not key:
                raise SystemExit(f"merge: {path} has a row without a key")
            if key in by_key and by_key[key].get("energy_loss_J") != row.get("energy_loss_J"):
                raise SystemExit(f"merge: key {key} has different results in two files")
            by_key.setdefault(key, row)
    return [by_key[k] for k in sorted(by_key)]
