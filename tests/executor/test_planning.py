import math

import numpy as np
import pytest

from assistant.executor import (
    ExecutionStatus,
    NoPathError,
    build_occupancy,
    entity_mask_on,
    plan_path,
)
from assistant.geometry import GridMap, Pose2D, box_polygon
from assistant.world import Entity, EntityKind, furniture_entities, load_world, world_grid


@pytest.fixture(scope="module")
def training_home():
    return load_world("training-home")


def perceived(world, scene="original", resolution_m=0.1):
    """Furniture as perception would report it (here: the ground truth on perception's grid)."""
    return furniture_entities(world, scene, world_grid(world, resolution_m))


def crosses_door(path, door, horizontal):
    """Whether a path crosses the door's line within its opening."""
    cx, cy = door.centre
    half = door.width_m / 2
    pts = path.waypoints
    for a, b in zip(pts[:-1], pts[1:]):
        if horizontal and (a[1] - cy) * (b[1] - cy) < 0:
            x = a[0] + (cy - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            if abs(x - cx) < half:
                return True
        if not horizontal and (a[0] - cx) * (b[0] - cx) < 0:
            y = a[1] + (cx - a[0]) / (b[0] - a[0]) * (b[1] - a[1])
            if abs(y - cy) < half:
                return True
    return False


def door(world, name):
    return next(d for d in world.floorplan.doors if d.name == name)


def assert_clear(occ, path):
    pts = path.waypoints
    for a, b in zip(pts[:-1], pts[1:]):
        # the straight segments stay out of the blocked zone (one cell of rasterisation slack)
        assert occ.segment_clearance(a, b) >= occ.robot_radius_m + occ.margin_m - occ.grid.resolution_m


def test_path_through_the_living_room_door_of_the_apartment(apartment):
    occ = build_occupancy(apartment, perceived(apartment))
    path = plan_path(occ, apartment.start, (5.5, 5.5))
    assert crosses_door(path, door(apartment, "living room door"), horizontal=True)
    assert np.allclose(path.waypoints[0], apartment.start.xy)
    assert np.allclose(path.waypoints[-1], (5.5, 5.5))
    assert not path.goal_snapped
    assert_clear(occ, path)
    # it keeps to the middle of the 1.22 m door rather than grazing a jamb
    assert path.min_clearance_m >= 0.45
    # simplified: a handful of waypoints, not one per grid cell
    assert len(path.waypoints) < len(path.grid_cells) / 5
    straight = math.dist(apartment.start.xy, (5.5, 5.5))
    assert straight < path.length_m < 2.5 * straight


def test_paths_between_the_rooms_of_the_training_home(training_home):
    occ = build_occupancy(training_home, perceived(training_home))
    to_bedroom = plan_path(occ, training_home.start, (8.5, 1.5))
    assert crosses_door(to_bedroom, door(training_home, "bedroom door"), horizontal=False)
    to_living = plan_path(occ, training_home.start, (2.5, 2.5))  # the living room's centre
    assert crosses_door(to_living, door(training_home, "living room door"), horizontal=False)
    across = plan_path(occ, (2.5, 2.5), (8.5, 2.0))
    assert crosses_door(across, door(training_home, "living room door"), horizontal=False)
    assert crosses_door(across, door(training_home, "bedroom door"), horizontal=False)
    for path in (to_bedroom, to_living, across):
        assert_clear(occ, path)


def test_modified_scene_plans_too(training_home):
    occ = build_occupancy(training_home, perceived(training_home, "modified"))
    path = plan_path(occ, training_home.start, (2.5, 2.5))
    assert_clear(occ, path)


def test_a_blocked_door_gives_a_clear_no_path_outcome(apartment):
    grid = world_grid(apartment, 0.05)
    d = door(apartment, "bedroom door")
    cx, cy = d.centre
    boxes = Entity.from_polygon("box_1", "box", EntityKind.SHORT_TERM,
                                box_polygon(cx - 0.7, cy - 0.4, cx + 0.7, cy + 0.4), grid)
    occ = build_occupancy(apartment, perceived(apartment) + [boxes])
    with pytest.raises(NoPathError) as caught:
        plan_path(occ, apartment.start, (0.0, -4.0))
    assert caught.value.reason == "unreachable"
    result = caught.value.to_result()
    assert result.status is ExecutionStatus.NO_PATH and not result.success
    assert "blocked" in result.message
    # the other door still works
    plan_path(occ, apartment.start, (5.5, 5.5))


def test_a_goal_inside_furniture_snaps_to_the_nearest_free_cell(apartment):
    occ = build_occupancy(apartment, perceived(apartment))
    coffee_table = (4.5, 4.0)  # the glasses case's table
    assert not occ.is_free(*coffee_table)
    path = plan_path(occ, apartment.start, coffee_table)
    assert path.goal_snapped
    assert 0.3 < path.snap_distance_m < 1.0
    assert occ.is_free(*path.goal)
    assert math.dist(path.goal, coffee_table) < 1.0
    assert path.requested_goal == coffee_table
    with pytest.raises(NoPathError) as caught:
        plan_path(occ, apartment.start, coffee_table, snap_goal=False)
    assert caught.value.reason == "goal_blocked"


def test_furniture_comes_only_from_the_entities_given(apartment):
    couch = (4.5, 3.0)
    assert build_occupancy(apartment, []).is_free(*couch)
    assert not build_occupancy(apartment, perceived(apartment)).is_free(*couch)


def test_entities_on_a_coarser_grid_cover_their_footprint():
    fine = GridMap(0.05, 0.0, 0.0, 100, 100)
    coarse = GridMap(0.2, 0.0, 0.0, 25, 25)
    square = box_polygon(1.0, 1.0, 2.0, 2.6)
    entity = Entity.from_polygon("t", "table", EntityKind.SHORT_TERM, square, coarse)
    mask = entity_mask_on(entity, fine)
    direct = fine.rasterize_polygon(square)
    assert (mask & direct).sum() == direct.sum()  # nothing under the footprint is missed
    assert mask.sum() < direct.sum() * 1.5


def test_a_start_against_a_wall_escapes(apartment):
    occ = build_occupancy(apartment, perceived(apartment))
    start = Pose2D(0.0, 1.0, 0.0)  # 0.26 m from the hallway's north wall
    assert not occ.is_free(start.x, start.y)
    path = plan_path(occ, start, (0.0, -0.5))
    assert math.dist(path.goal, (0.0, -0.5)) < 1e-9


def test_goals_outside_the_home_are_refused(apartment):
    occ = build_occupancy(apartment, [])
    with pytest.raises(NoPathError) as caught:
        plan_path(occ, apartment.start, (100.0, 100.0))
    assert caught.value.reason == "outside"
    with pytest.raises(NoPathError):  # beyond the outer wall, in unknown floor
        plan_path(occ, apartment.start, (7.6, 4.0), max_snap_m=0.2)


def test_cost_is_lower_in_open_floor(apartment):
    occ = build_occupancy(apartment, [])
    cost = occ.cost()
    open_floor, near_wall = occ.cells_of(np.array([[4.5, 4.5], [4.5, 7.45]]))
    assert cost[tuple(open_floor)] == pytest.approx(1.0)
    assert 1.0 < cost[tuple(near_wall)] < np.inf


def test_reachable_from_leaves_out_pockets_the_robot_cannot_drive_into():
    from assistant.executor.planning import OccupancyMap
    from assistant.geometry import GridMap, Pose2D

    grid = GridMap(0.1, 0.0, 0.0, 40, 40)  # 4 m × 4 m
    obstacles = np.zeros(grid.shape, dtype=bool)
    obstacles[:, 20] = True  # a wall across the middle: x = 2.0–2.1 m
    occ = OccupancyMap.from_obstacles(grid, obstacles)
    pts = np.array([[1.0, 2.0], [3.0, 2.0], [9.0, 9.0]])
    assert occ.reachable_from(Pose2D(0.5, 2.0, 0.0), pts).tolist() == [True, False, False]
    assert occ.reachable_from(Pose2D(3.5, 2.0, 0.0), pts).tolist() == [False, True, False]
    assert occ.reachable_from(Pose2D(0.5, 2.0, 0.0), np.zeros((0, 2))).shape == (0,)
