"""The command line's progress bar and per-mesh error lines."""
import time


class _Progress:
    """A one-line progress bar on stderr when it is a terminal."""

    def __init__(self, stream, enabled, quiet):
        self.stream, self.enabled, self.quiet = stream, enabled, quiet
        self.t0 = time.perf_counter()
        self.counts = {"ok": 0, "skipped": 0, "error": 0}
        self.drawn = False

    def __call__(self, row, done, total):
        self.counts[row["status"]] = self.counts.get(row["status"], 0) + 1
        if row["status"] == "error" and not self.quiet:
            self.clear()
            print(f"gsp-batch: {row['input']}: {row['error']}", file=self.stream)
        if self.enabled:
            width = 30
            filled = int(width * done / max(total, 1))
            c = self.counts
            line = (f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total}  ok {c['ok']}  "
                    f"skipped {c['skipped']}  error {c['error']}  {time.perf_counter() - self.t0:.1f} s")
            self.stream.write(line)
            self.stream.flush()
            self.drawn = True

    def clear(self):
        if self.drawn:
            self.stream.write("\r\033[K")
            self.stream.flush()
            self.drawn = False
