"""toyhost.farm on dask.distributed: a LocalCluster of 2 worker processes (each with its own GL
context) renders 4 shards, each seeking to its first frame (Session.seek), byte-identical to one
run, for a shadertoy without buffers and one with a simulation buffer and a mouse script, with
`every` too (a shard renders only from the first to the last frame it keeps); toyhost.farm.map renders several shadertoys and
brings back only what `reduce` returns. Debian's python3-distributed (scripts/install-deps.sh):
the test fails, it does not skip, when it is missing."""

import numpy
import pytest

import toyhost
import toyhost.farm
from support import DATE, SOURCE_DIR


POOL = SOURCE_DIR / "shadertoys" / "ripple-pool"
OCEAN = SOURCE_DIR / "shadertoys" / "exp-sine-ocean"


@pytest.fixture(scope="module")
def client():
    from dask.distributed import Client, LocalCluster  # ImportError fails the tests
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as c:
            yield c


def single_run(path, frames, every=1, **options):
    with toyhost.Session(toyhost.load(path), **options) as session:
        return list(session.render(frames, every=every))


@pytest.mark.parametrize("path, options", [
    (OCEAN, {}),
    (POOL, {"mouse_script": POOL / "drag.json"}),
], ids=["image-only", "buffers"])
def test_four_shards_on_two_workers_equal_one_run(client, path, options):
    options = dict(size=(64, 36), date=DATE, **options)
    expected = single_run(path, 22, **options)
    got = list(toyhost.farm.render(path, 22, client=client, shards=4, **options))
    assert [i for i, _ in got] == list(range(22))
    for (i, a), (j, b) in zip(got, expected):
        assert i == j
        assert a.dtype == numpy.uint8 and a.shape == (36, 64, 4)
        assert numpy.array_equal(a, b), f"frame {i} differs from the single run"
    # Both workers took part: each shard ran in a worker process, not here.
    assert len(client.scheduler_info()["workers"]) == 2


@pytest.mark.parametrize("every, kept", [
    (5, [0, 5, 10, 15, 20, 22]),
    (10, [0, 10, 20, 22]),  # shard 2 (frames 11-16) keeps none: it renders nothing
], ids=["every-5", "a-shard-keeps-none"])
def test_every_keeps_the_single_runs_frames(client, every, kept):
    options = dict(size=(32, 18), date=DATE, mouse_script=POOL / "drag.json")
    expected = single_run(POOL, 23, every=every, **options)
    got = list(toyhost.farm.render(POOL, 23, client=client, shards=4, every=every, **options))
    assert [i for i, _ in got] == [i for i, _ in expected] == kept
    assert all(numpy.array_equal(a, b) for (_, a), (_, b) in zip(got, expected))


def mean_level(path, frames):
    return float(numpy.mean(frames[-1][1][..., :3]))


def test_map_renders_each_shadertoy_and_returns_what_reduce_keeps(client):
    paths = [OCEAN, POOL]
    results = list(toyhost.farm.map(paths, 6, client=client, reduce=mean_level, size=(32, 18), date=DATE))
    assert [p for p, _ in results] == [str(p) for p in paths]
    for path, level in results:
        frames = single_run(path, 6, size=(32, 18), date=DATE)
        assert level == pytest.approx(float(numpy.mean(frames[-1][1][..., :3])), abs=0)


def test_shard_spans_match_the_cli_and_refuse_bad_counts(monkeypatch):
    assert toyhost.farm.shard_spans(10, 3) == [(0, 3), (3, 6), (6, 10)]
    assert toyhost.farm.shard_spans(2000000000, 16)[-1] == (1875000000, 2000000000)
    # The arithmetic is the library's (toyhost::shardSpan, as --shard and farm plan split), not a copy.
    assert toyhost._toyhost.shard_span(10, 3, 1) == (3, 6)
    with pytest.raises(toyhost.UsageError):
        toyhost._toyhost.shard_span(10, 3, 3)
    asked = []
    real = toyhost._toyhost.shard_span
    monkeypatch.setattr(toyhost._toyhost, "shard_span", lambda *a: asked.append(a) or real(*a))
    assert toyhost.farm.shard_spans(7, 2) == [(0, 3), (3, 7)]
    assert asked == [(7, 2, 0), (7, 2, 1)]
    monkeypatch.undo()
    with pytest.raises(toyhost.UsageError, match="expected 1 <= shards <= frames"):
        toyhost.farm.shard_spans(3, 4)
    with pytest.raises(toyhost.UsageError):
        toyhost.farm.shard_spans(2**31, 2)
    with pytest.raises(toyhost.UsageError):
        toyhost.farm.render(12345, 4, client=None).__next__()


def test_no_client_takes_the_current_one_or_says_what_is_missing(client, monkeypatch):
    """client=None: Dask's current client (a `with Client(...)`), never an AttributeError (issue 45)."""
    got = list(toyhost.farm.render(POOL, 2, client=None, shards=2, size=(16, 8), date=DATE))
    assert [iframe for iframe, _array in got] == [0, 1]

    def no_client():
        raise ValueError("No clients found")  # what dask says outside any `with Client(...)`
    import distributed
    monkeypatch.setattr(distributed, "get_client", no_client)
    with pytest.raises(toyhost.UsageError, match="no current Dask client"):
        list(toyhost.farm.render(POOL, 2, client=None, shards=2, size=(16, 8), date=DATE))
