import pytest

import glyphbench_rl
from glyphbench_rl.core import list_tasks

ALL_TASKS = list_tasks()


def pytest_report_header(config):
    return f"glyphbench_rl {glyphbench_rl.__version__}: {len(ALL_TASKS)} registered tasks"


@pytest.fixture(params=ALL_TASKS)
def task_id(request):
    return request.param
