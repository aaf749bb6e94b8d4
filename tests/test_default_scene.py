"""`make run`'s contact part: the default scene runs, agrees with the corrected closed form
(an independent oracle, tests/test_closed_form.py) and writes its figure."""
from validation.default_scene import main


def test_default_scene_runs_and_agrees_with_closed_form(tmp_path, capsys):
    out = main(out=tmp_path)
    assert out["agree"] <= 1e-10
    assert out["png"].exists() and out["png"].stat().st_size > 10_000
    text = capsys.readouterr().out
    assert "contact ends" in text and "Rayleigh speed" in text
