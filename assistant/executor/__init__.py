"""The executor: robot tasks (fetch, search) over one explicit :class:`TaskContext`, room
entry, choosing furniture, path planning, motion control, localization.

Outcomes are values (:class:`ExecutionResult` with an :class:`ExecutionStatus`), never
exceptions for things that happen in a home. Planning reads the floor plan the robot is told
and the furniture perception reports; motion drives any robot through its shared interface.
"""

from assistant.executor.choosing import PlaceChooser, Said
from assistant.executor.context import BudgetSpent, TaskContext
from assistant.executor.entry import enter_room
from assistant.executor.fetch import FETCH_BUDGET_S, FetchTask
from assistant.executor.localization import FloorplanLocalizer, LocalizationUpdate, wall_faces
from assistant.executor.motion import (
    DrivableRobot,
    Localizer,
    MotionLimits,
    PathFollower,
    face_point,
    follow_path,
    turn_to,
)
from assistant.executor.navigation import Navigator
from assistant.executor.obstacles import DepthObstacles
from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.executor.reports import FetchResult, NodeReport
from assistant.executor.planning import (
    NoPathError,
    OccupancyMap,
    PlannedPath,
    build_occupancy,
    entity_mask_on,
    plan_path,
)
from assistant.executor.rooms import DoorCrossing, RoomGraph, door_crossing, room_entry_waypoints, room_of
from assistant.executor.sensing import (
    PERCEPTION_MODES,
    FurnitureSource,
    OracleFurniture,
    SensedFurniture,
    make_furniture_source,
)
from assistant.executor.search import SEARCH_BUDGET_S, SearchResult, SearchTask, room_order
from assistant.executor.sightings import place_sightings
from assistant.executor.trial import is_visible, object_visibility

__all__ = [
    "BudgetSpent", "FETCH_BUDGET_S", "FetchResult", "FetchTask", "FurnitureSource", "NodeReport",
    "OracleFurniture", "PERCEPTION_MODES", "PlaceChooser", "SEARCH_BUDGET_S", "Said", "SearchResult", "SearchTask",
    "SensedFurniture", "TaskContext", "enter_room", "room_order", "place_sightings", "is_visible", "make_furniture_source", "object_visibility",
    "DepthObstacles", "DoorCrossing", "DrivableRobot", "ExecutionResult", "ExecutionStatus", "FloorplanLocalizer",
    "LocalizationUpdate", "Localizer", "MotionLimits", "Navigator", "NoPathError",
    "OccupancyMap", "PathFollower", "PlannedPath", "RoomGraph", "build_occupancy", "door_crossing",
    "entity_mask_on", "face_point", "follow_path", "plan_path", "room_entry_waypoints", "room_of",
    "turn_to", "wall_faces",
]
