"""`python3 -m gsp.batch`: the command line."""
import sys

if __name__ == "__main__":
    # Nothing is defined here, in __main__: the tasks are gsp.batch.task's functions, pickled by
    # reference (the workers import gsp.batch), not by value.
    from gsp.batch.cli import main
    sys.exit(main())
