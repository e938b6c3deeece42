"""A progress bar for long renders from Python (Scene.render's `progress`): text on stderr,
redrawn in place with a carriage return, which terminals and Jupyter both show as one line."""
import sys
import time

# Without progress=True, the bar appears only once a render has run this long.
AUTO_DELAY_SECONDS = 1.0
WIDTH = 30


class RenderProgress:
    """Called with the number of image rows done (of `total`) after each band of rows."""

    def __init__(self, total, delay, stream=None):
        self.total, self.delay = total, delay
        self.stream = stream if stream is not None else sys.stderr
        self.start = time.monotonic()
        self.shown = False

    def __call__(self, done):
        elapsed = time.monotonic() - self.start
        if not self.shown and elapsed < self.delay and done < self.total:
            return
        self.shown = True
        filled = WIDTH * done // self.total
        line = (f"\rrendering |{'#' * filled}{'.' * (WIDTH - filled)}| {done}/{self.total} "
                f"rows, {elapsed:.1f} s")
        self.stream.write(line + ("\n" if done >= self.total else ""))
        self.stream.flush()


def render_progress(progress, total):
    """The bar for `progress` (True: at once, None: after AUTO_DELAY_SECONDS, False: none)."""
    if progress is False:
        return None
    if progress is True:
        return RenderProgress(total, 0.0)
    if progress is None:
        return RenderProgress(total, AUTO_DELAY_SECONDS)
    raise TypeError(f"progress must be True, False or None (automatic), got {progress!r}")
