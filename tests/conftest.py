import pytest

import glyphbench_rl
from glyphbench_rl.core import list_tasks

ALL_TASKS = list_tasks()


def pytest_report_header(config):
    return f"glyphbench_rl {glyphbench_rl.__version__}: {len(ALL_TASKS)} registered tasks"


@pytest.fixture(params=ALL_TASKS)
def task_id(request):
    return request.param


@pytest.fixture(scope="session")
def tiny_model_dir(tmp_path_factory):
    """A tiny random Llama with a ChatML tokenizer trained offline (built once per session)."""
    pytest.importorskip("transformers")
    from glyphbench_rl.models import make_tiny_model
    return make_tiny_model(tmp_path_factory.mktemp("tiny-model"))
