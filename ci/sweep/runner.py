"""Runs configurations through the console runner (build/bin/charpy --json) in parallel.

A configuration is a dict: 'key' (unique name), 'flags' (runner flags) and any other columns,
which are copied into its CSV row next to the runner's JSON fields.
"""
import concurrent.futures
import functools
import hashlib
import json
import os
import subprocess
import sys
import time

from . import csvfile


def parse_shard(text):
    """'i/n' (1 <= i <= n) -> (i, n)."""
    try:
        i, n = (int(x) for x in text.split("/"))
    except ValueError:
        raise SystemExit(f"--shard: '{text}' is not i/n with whole numbers 1 <= i <= n")
    if not 1 <= i <= n:
        raise SystemExit(f"--shard: '{text}' is not i/n with whole numbers 1 <= i <= n")
    return i, n


def in_shard(configurations, shard):
    """The configurations of shard (i, n): every n-th one, starting at the i-th."""
    i, n = shard
    return [c for index, c in enumerate(configurations) if index % n == i - 1]


@functools.lru_cache(maxsize=None)
def runner_id(path):
    """First 16 hex digits of the SHA-256 of the runner's file: a row made by another build is not reused."""
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()[:16]


def run_one(runner, configuration, timeout_s, accept_codes=(0,), keep_json=False):
    """One run: the CSV row (configuration columns + JSON fields, or a 'failure' column).

    accept_codes: the exit codes whose JSON counts (a runner may print its JSON and exit with a verdict code);
    keep_json: the whole JSON also goes in a 'json' column, for reports that read lists and types back.
    """
    row = {k: v for k, v in configuration.items() if k not in ("flags", "runner")}
    row["flags"] = " ".join(configuration["flags"])
    runner = configuration.get("runner") or runner
    row["runner_id"] = runner_id(runner)
    try:
        done = subprocess.run([runner, "--json"] + configuration["flags"], capture_output=True, text=True, timeout=timeout_s)
    except subprocess.TimeoutExpired:
        row["failure"] = f"timeout after {timeout_s} s"
        return row
    if done.returncode not in accept_codes:
        row["failure"] = f"exit {done.returncode}: {done.stderr.strip()[:200]}"
        return row
    try:
        result = json.loads(done.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        row["failure"] = "no JSON on stdout"
        return row
    row.update({k: (int(v) if isinstance(v, bool) else v) for k, v in result.items()})
    if keep_json:
        row["json"] = json.dumps(result)
    return row


def as_csv_text(row):
    """A row's values as the CSV holds them (text; None empty), so fresh and resumed rows compare alike."""
    return {k: "" if v is None else str(v) for k, v in row.items()}


def journal_path(out_csv):
    """Where run_all appends each finished row (one JSON line) until it writes the CSV whole."""
    return out_csv + ".journal"


def read_journal(out_csv):
    """Rows an interrupted sweep left in its journal, their values as the CSV would hold them (text)."""
    path = journal_path(out_csv)
    if not os.path.exists(path):
        return []
    rows = []
    with open(path) as f:
        for line in f:
            try:
                row = json.loads(line)
            except ValueError:
                continue  # the last line of a sweep killed while it wrote
            rows.append(as_csv_text(row))
    return rows


def run_all(runner, configurations, out_csv, jobs, timeout_s=600, first_columns=("key",), log=sys.stderr, accept_codes=(0,), keep_json=False):
    """Runs every configuration not yet in out_csv, keeping the finished rows; returns all rows, as text (as_csv_text).

    Each finished run is appended to out_csv's journal (journal_path: one JSON line, cheap however many rows there
    are) and out_csv is written whole when the sweep ends, so an interrupted sweep loses nothing: the next call takes
    the journal's rows as finished, folds them into the CSV and resumes where it stopped. A row is reused only if the
    same runner binary made it (runner_id): after a rebuild that changed the runner every row is run again.
    """
    if not os.access(runner, os.X_OK):
        raise SystemExit(f"runner {runner} not found or not executable (build it: cmake --build build --target charpy)")
    keys = [c["key"] for c in configurations]
    if len(set(keys)) != len(keys):
        raise SystemExit("configurations have duplicate keys")
    os.makedirs(os.path.dirname(os.path.abspath(out_csv)), exist_ok=True)  # a fresh build tree has no sweep folder yet
    expected_id = {c["key"]: runner_id(c.get("runner") or runner) for c in configurations}
    by_key = {}
    for r in csvfile.read_rows(out_csv) + read_journal(out_csv):  # a journal's row is newer than the CSV's
        if r.get("key") in expected_id and not r.get("failure") and r.get("runner_id") == expected_id[r["key"]]:
            by_key[r["key"]] = r
    order = {k: i for i, k in enumerate(keys)}
    rows = sorted(by_key.values(), key=lambda r: order[r["key"]])
    journal = journal_path(out_csv)
    if os.path.exists(journal):
        csvfile.write_rows(out_csv, rows, first_columns)
        os.remove(journal)
    finished = {r["key"] for r in rows}
    todo = [c for c in configurations if c["key"] not in finished]
    total = len(configurations)
    print(f"{len(finished)}/{total} already in {out_csv}, {len(todo)} to run on {jobs} jobs", file=log)
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(run_one, runner, c, timeout_s, accept_codes, keep_json) for c in todo]
        for n, future in enumerate(concurrent.futures.as_completed(futures), 1):
            row = future.result()
            rows.append(row)
            with open(journal, "a") as f:
                f.write(json.dumps(row) + "\n")
            elapsed = time.monotonic() - start
            eta = elapsed / n * (len(todo) - n)
            print(f"\r{len(finished) + n}/{total} done, {elapsed:.0f} s, ETA {eta:.0f} s   ", end="", file=log, flush=True)
    if todo:
        print(file=log)
        rows.sort(key=lambda r: order[r["key"]])
        csvfile.write_rows(out_csv, rows, first_columns)
        os.remove(journal)
    return [as_csv_text(r) for r in rows]
