"""How a batch reports trouble: UsageError when it cannot start, one line per failed mesh."""


class UsageError(ValueError):
    """A batch that cannot start: unknown job, no inputs, bad options (the command line exits 2)."""


def _one_line(e):
    lines = str(e).strip().splitlines()
    return f"{type(e).__name__}: {lines[0]}" if lines else type(e).__name__
