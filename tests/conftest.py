"""Shared test set-up: the campaign's run cache goes to a temporary folder, never to the user's
cache folder (``$SLINGLOADS_CACHE`` is read by ``slingloads.runs.cache``)."""

import pytest


@pytest.fixture(autouse=True, scope="session")
def _campaign_cache(tmp_path_factory):
    patch = pytest.MonkeyPatch()
    patch.setenv("SLINGLOADS_CACHE", str(tmp_path_factory.mktemp("campaign-cache")))
    yield
    patch.undo()


@pytest.fixture(scope="session")
def example_results():
    """The example workbook's study, every analysis run once for the whole session."""
    from pathlib import Path

    import slingloads as sl

    root = Path(__file__).resolve().parents[1]
    return sl.read_study(root / "loadcases" / "example-light-twin.xlsx").run()


@pytest.fixture(scope="session", params=["SI", "US"])
def example_reports(request, example_results, tmp_path_factory):
    """(units, folder) of the example's reports written in SI and in US units."""
    import slingloads as sl

    out = tmp_path_factory.mktemp(f"example-{request.param}")
    sl.write_reports(example_results, out, request.param)
    return request.param, out
