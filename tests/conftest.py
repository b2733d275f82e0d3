"""Shared test set-up: the campaign's run cache goes to a temporary folder, never to the user's
cache folder (``$SLINGLOADS_CACHE`` is read by ``slingloads.runs.cache``)."""

import pytest


@pytest.fixture(autouse=True, scope="session")
def _campaign_cache(tmp_path_factory):
    patch = pytest.MonkeyPatch()
    patch.setenv("SLINGLOADS_CACHE", str(tmp_path_factory.mktemp("campaign-cache")))
    yield
    patch.undo()
