"""listener_check: eval generation's listener figure, used by the where_is notebook too."""

from __future__ import annotations

from types import SimpleNamespace

from assistant.errors import AssistantError
from assistant.eval.generation import listener_check


class _Fetcher:
    """Records the fetch it is asked for and answers as ``Fetcher.fetch`` does."""

    def __init__(self, success=True, error=None):
        self.calls, self.success, self.error = [], success, error

    def fetch(self, text, world, scene, perception, object_name=None, on_pose=None):
        self.calls.append((text, world, scene, perception, object_name))
        if self.error:
            raise self.error
        if on_pose is not None:
            on_pose("pose")
        return SimpleNamespace(success=self.success, data={
            "failure": None if self.success else "not_visible",
            "executor": {"message": "facing the table", "target_furniture": {"centre": [1.0, 2.0]}},
            "nodes": [{"rdt": "couch-back-table"}]})


def test_the_description_is_fetched_for_the_object_with_the_given_perception():
    fetcher, poses = _Fetcher(), []
    said = SimpleNamespace(found=True, description="The fork is on the table behind the couch.")
    check = listener_check(fetcher, said, "apartment", "original", "fork", "oracle", on_pose=poses.append)
    assert fetcher.calls == [(said.description, "apartment", "original", "oracle", "fork")]
    assert check == {"success": True, "failure": None, "message": "facing the table", "target": [1.0, 2.0],
                     "nodes": ["couch-back-table"]}
    assert poses == ["pose"]


def test_a_failed_or_impossible_check_says_why():
    said = SimpleNamespace(found=True, description="The fork is somewhere.")
    assert listener_check(_Fetcher(success=False), said, "apartment", "original", "fork")["failure"] == "not_visible"
    broken = listener_check(_Fetcher(error=AssistantError("no path")), said, "apartment", "original", "fork")
    assert broken["success"] is False and "no path" in broken["failure"]
    unseen = listener_check(_Fetcher(), SimpleNamespace(found=False, description=""), "apartment", "original", "fork")
    assert unseen == {"success": False, "failure": "not found by the search"}
    assert listener_check(None, said, "apartment", "original", "fork") is None
