"""Running the console runner over many configurations: CSV files, shards, resume, progress."""
