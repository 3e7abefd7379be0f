"""Stand-ins shared by the dialogue tests: what the application layer returns for a fetch."""

from __future__ import annotations


def fetch_result(success: bool, furniture: str, obj: str = "mug", seen_objects=(), perceived=None):
    """A fetch's application-layer result as the stand-in fetchers report it."""
    from assistant.app import Result, Status

    data = {"success": success, "failure": None if success else "not_visible", "final_pose": [1.0, 2.0, 0.0],
            "executor": {"status": "success", "message": "facing the table",
                         "target_furniture": {"id": furniture, "name": "table", "centre": [0, 0]}}}
    return Result("fetch", Status.SUCCESS if success else Status.NOT_VISIBLE, "facing the table", data,
                  seen=list(seen_objects), furniture=perceived, object=obj, object_seen=success)
