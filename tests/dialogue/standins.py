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


class RecordingFetcher:
    """A stand-in fetcher that keeps each command it is given (``texts``) and ends at
    ``furniture``; with ``hold`` its first task keeps reporting progress until the manager stops
    it (the progress callback raises)."""

    def __init__(self, furniture: str = "couch_1", hold: bool = False):
        self.furniture, self.hold, self.texts = furniture, hold, []

    def __call__(self, text, world, scene, on_event):
        import time

        self.texts.append(text)
        while self.hold and len(self.texts) == 1:
            time.sleep(0.01)
            on_event("move_to", {"goal": None})
        return fetch_result(True, self.furniture)
