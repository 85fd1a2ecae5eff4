"""Many scenes or sections at once, on dask.distributed (Debian: python3-distributed).

    results = plascap.sweep(plascap.run_scene, scenes)                  # a local cluster
    results = plascap.sweep(f, items, scheduler="tcp://10.0.0.5:8786")  # an existing one

Each item is computed by one task, `function(item)` (with `kwargs`), on a worker process; the
results come back in the order of the items. `table()` turns a list of flat dicts into a pandas
DataFrame where pandas is installed, else returns the list.
"""


def sweep(function, items, scheduler=None, workers=2, **kwargs):
    """[function(item, **kwargs) for item in items], computed on a dask cluster.

    scheduler: the address of a running dask scheduler; None starts a local cluster of `workers`
    single-threaded processes for the sweep and closes it after."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError as missing:
        raise ImportError("plascap.sweep needs dask.distributed (Debian: python3-distributed)") from missing
    items = list(items)
    if scheduler is None:
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            return client.gather(client.map(function, items, pure=False, **kwargs))
    with Client(scheduler) as client:
        return client.gather(client.map(function, items, pure=False, **kwargs))


def table(rows):
    """A list of flat dicts as a pandas DataFrame (pandas installed) or as the list itself."""
    try:
        import pandas
    except ImportError:
        return list(rows)
    return pandas.DataFrame(list(rows))
