"""``assistant warm-up`` (make run's and make notebook's set-up step) prepares every model the chat uses."""

import json

from assistant.cli import main


def test_warm_up_prepares_each_model_and_says_so(capsys):
    assert main(["warm-up", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert [s["what"] for s in report["steps"]] == [
        "language and grounding models", "description model", "policy models", "furniture detector"]
    assert report["world"] == "apartment" and report["seconds"] >= 0
