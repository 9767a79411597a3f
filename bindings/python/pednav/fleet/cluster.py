# SPDX-License-Identifier: Apache-2.0
"""The Dask client of a fleet run: a LocalCluster on loopback by default, or
the scheduler of a real cluster."""
import sys


def connect(scheduler=None, workers=2, threads_per_worker=1):
    """A dask.distributed Client: of `scheduler` ("tcp://host:8786") when
    given, else of a new LocalCluster of `workers` processes (one engine at a
    time each) listening on 127.0.0.1 only, without a dashboard. Closing the
    client closes a cluster it made."""
    from dask.distributed import Client, LocalCluster

    if scheduler:
        return Client(scheduler)
    cluster = LocalCluster(n_workers=workers, threads_per_worker=threads_per_worker, processes=True,
                           host="127.0.0.1", dashboard_address=None, silence_logs=40)
    client = Client(cluster)
    client._pednav_cluster = cluster  # closed with the client (close_client)
    return client


def close_client(client):
    cluster = getattr(client, "_pednav_cluster", None)
    client.close()
    if cluster is not None:
        cluster.close()


class Progress:
    """A one-line progress display on a stream: done/total, failures, rate."""

    def __init__(self, total, what="walks", stream=None, enabled=True):
        self.total = total
        self.what = what
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.done = 0
        self.failed = 0
        import time
        self._clock = time.perf_counter
        self._start = self._clock()

    def update(self, failed=False):
        self.done += 1
        self.failed += 1 if failed else 0
        if not self.enabled:
            return
        width = 30
        filled = width * self.done // max(1, self.total)
        elapsed = self._clock() - self._start
        rate = self.done / elapsed if elapsed > 0 else 0.0
        end = "\n" if self.done == self.total else ""
        self.stream.write("\r[%s%s] %d/%d %s, %d failed, %.2f %s/s%s" % (
            "#" * filled, " " * (width - filled), self.done, self.total, self.what, self.failed, rate, self.what,
            end))
        self.stream.flush()
