"""Render farms from Python: a render's shards, or many shadertoys, on Dask workers.

    from dask.distributed import Client, LocalCluster
    import toyhost.farm
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        for iframe, rgba in toyhost.farm.render("shadertoys/ocean", 240, client=client, shards=8,
                                                size=(320, 180), date="2024-01-01T00:00:00"):
            ...                                   # frames in order, (height, width, 4) uint8

Each shard is one Dask task: the worker loads the shadertoy itself and renders in a Session of its
own (its own GL context, on the worker process's GL thread), so give paths every worker can read.
A shard seeks to its first frame (Session.seek, as `toyhost run --frame-range` does): a shadertoy
without buffers renders nothing before it, one with buffers (or Cube A) simulates its past with
Image skipped in every shard (the CLI's `toyhost farm plan` starts shards from checkpoints
instead). The frames are the single run's, byte for byte: shard boundaries are those of
`toyhost run --shard i/n` (toyhost::shardSpan, through the native module). Session options (size, fps, date, mouse_script,
...) are passed on to every shard's Session; fix ``date`` where iDate matters, as the workers'
clocks differ. dask.distributed is imported only by the functions that take a client.
"""

import os

from . import _args as args

__all__ = ["shard_spans", "render", "map"]


def shard_spans(frames, shards):
    """The (first, end) frame ranges of `shards` shards of `frames` frames, as --shard i/n splits them."""
    from . import UsageError, _args, _toyhost
    if not isinstance(frames, int) or not isinstance(shards, int) or frames < 1 or not 1 <= shards <= frames:
        raise UsageError(f"shards: expected 1 <= shards <= frames, got {shards} shards of {frames} frames")
    _args.integer("frames", frames)  # a run's frames are a 32-bit count, as the CLI's --frames
    return [_toyhost.shard_span(frames, shards, i) for i in range(shards)]


def _source(shadertoy):
    """What a worker loads: a path (str or PathLike), or the path a loaded Shadertoy came from."""
    from . import Shadertoy, UsageError
    if isinstance(shadertoy, Shadertoy):
        shadertoy = shadertoy.path
    if not isinstance(shadertoy, (str, os.PathLike)):
        raise UsageError(f"shadertoy: expected a path every worker can read, got {type(shadertoy).__name__}")
    return os.fspath(shadertoy)


def _render_shard_task(source, first, end, last, every, pass_, dtype, options):
    """On a worker: the frames of first .. end-1 that the single run yields (iFrame a multiple of
    `every`, and the run's last frame `last`). The session seeks to the first of them and renders
    to the last of them: render() counts `every` on iFrame and yields its own last frame, which is
    one of those."""
    import toyhost
    start = -(-first // every) * every  # the first multiple of every from `first` on
    stop = end if end - 1 == last else min(end, (end - 1) // every * every + 1)
    start = min(start, last)  # the run's last frame is handed over whatever its number
    if start >= stop:
        return []  # nothing of the run's frames falls in this shard: no session needed
    with toyhost.Session(toyhost.load(source), **options) as session:
        session.seek(start)
        return list(session.render(stop - start, every=every, pass_=pass_, dtype=dtype))


def _client(client):
    """`client`, or Dask's current client when it is None (the one a `with Client(...)` made);
    UsageError when there is none."""
    if client is not None:
        return client
    try:
        from distributed import get_client
        return get_client()
    except (ImportError, ValueError) as e:
        raise args.usage("client", "is None and there is no current Dask client: give a "
                                   "dask.distributed Client (e.g. Client(LocalCluster()))") from e


def render(shadertoy, frames, client, shards=None, every=1, pass_="Image", dtype="uint8", **session_options):
    """Renders `frames` frames of `shadertoy` in `shards` Dask tasks (default: one per worker
    thread of `client`) and yields ``(iframe, array)`` in frame order, as Session.render does for
    one run: frame 0, every every-th and the last. A shard's frames come as soon as it and the
    shards before it are done; a task that fails raises its exception here."""
    source = _source(shadertoy)
    client = _client(client)
    if shards is None:
        shards = max(1, min(frames, sum(client.nthreads().values())))
    spans = shard_spans(frames, shards)
    futures = [client.submit(_render_shard_task, source, first, end, frames - 1, every, pass_, dtype,
                             dict(session_options), pure=False)
               for first, end in spans]
    try:
        for future in futures:
            yield from future.result()
    finally:
        for future in futures:
            future.cancel()


def _map_task(source, frames, every, pass_, dtype, reduce, options):
    import toyhost
    with toyhost.Session(toyhost.load(source), **options) as session:
        rendered = list(session.render(frames, every=every, pass_=pass_, dtype=dtype))
    return reduce(source, rendered) if reduce is not None else rendered


def map(shadertoys, frames, client, every=1, pass_="Image", dtype="uint8", reduce=None, **session_options):
    """Renders each of `shadertoys` (paths) for `frames` frames, one Dask task each, and yields
    ``(shadertoy, result)`` in the order given: the list of ``(iframe, array)`` (as
    Session.render), or, with ``reduce``, what ``reduce(path, frames)`` returns on the worker (a
    score, a verdict from toyhost.compare_images: only that comes back). A data set of frames, or
    an evaluation of generated shaders."""
    sources = [_source(s) for s in shadertoys]
    client = _client(client)
    futures = [client.submit(_map_task, source, frames, every, pass_, dtype, reduce, dict(session_options), pure=False)
               for source in sources]
    try:
        for source, future in zip(sources, futures):
            yield source, future.result()
    finally:
        for future in futures:
            future.cancel()
