import math

import numpy as np
import pytest

from assistant.perception.features import (
    FeatureParams,
    estimate_normals,
    normal_histogram,
    orientation_features,
    shape_descriptor,
)
from assistant.perception.samples import SampleParams, extract_samples


def box_points(cx, cy, sx, sy, z0, z1, step=0.02):
    """Points on the top and the four sides of a box (floor frame, metres)."""
    xs = np.arange(cx - sx / 2, cx + sx / 2 + 1e-9, step)
    ys = np.arange(cy - sy / 2, cy + sy / 2 + 1e-9, step)
    zs = np.arange(z0, z1 + 1e-9, step)
    top = np.array([(x, y, z1) for x in xs for y in ys])
    sides = [np.array([(x, y, z) for x in xs for z in zs]) for y in (ys[0], ys[-1])]
    sides += [np.array([(x, y, z) for y in ys for z in zs]) for x in (xs[0], xs[-1])]
    return np.vstack([top, *sides])


def test_two_boxes_make_two_samples_and_clutter_is_dropped():
    table = box_points(2.0, 0.5, 0.8, 0.8, 0.0, 0.5)
    couch = box_points(3.0, -1.5, 0.8, 2.0, 0.0, 0.9)
    clutter = box_points(1.0, 2.0, 0.15, 0.15, 0.0, 0.2)
    floor = np.array([(x, y, 0.0) for x in np.arange(0.5, 4, 0.1) for y in np.arange(-3, 3, 0.1)])
    samples, stats = extract_samples(np.vstack([table, couch, clutter, floor]))
    assert len(samples) == 2
    centres = sorted(tuple(s.footprint_centre_xy) for s in samples)
    assert centres[0] == pytest.approx((2.0, 0.5), abs=0.1)
    assert centres[1] == pytest.approx((3.0, -1.5), abs=0.11)
    assert stats["dropped_small"] == 1
    heights = sorted(s.height_m for s in samples)
    assert heights == pytest.approx([0.5, 0.9], abs=0.02)


def test_walls_and_tall_things_are_not_samples():
    wall = np.array([(3.0, y, z) for y in np.arange(-2, 2, 0.02) for z in np.arange(0.0, 1.6, 0.02)])
    wardrobe = box_points(2.0, 2.0, 0.6, 0.6, 0.0, 2.2)
    samples, stats = extract_samples(np.vstack([wall, wardrobe]))
    assert samples == []
    assert stats["dropped_wall"] == 1 and stats["cleared_cells"] > 0  # the wardrobe column is cleared


def test_columns_running_out_of_the_top_of_the_view_are_cleared():
    couch = box_points(3.0, 0.0, 0.8, 2.0, 0.0, 0.9)
    wall = np.array([(3.5, y, z) for y in np.arange(-2, 2, 0.02) for z in np.arange(0.0, 1.4, 0.02)])
    pts = np.vstack([couch, wall])
    rows = np.where(pts[:, 2] > 1.35, 0.0, 100.0)  # the wall's top is at the top of the image
    samples, stats = extract_samples(pts, rows, image_height=240)
    assert len(samples) == 1 and stats["cleared_cells"] > 0
    assert samples[0].footprint_centre_xy == pytest.approx([3.0, 0.0], abs=0.1)


def test_normal_histogram_of_a_table_top():
    params = FeatureParams()
    top = np.array([(x, y, 0.72) for x in np.arange(-0.4, 0.4, 0.03) for y in np.arange(-0.4, 0.4, 0.03)])
    normals = estimate_normals(top, np.array([-2.0, 0.0, 1.0]), params)
    assert np.all(normals[:, 2] > 0.95)  # up, towards the camera
    h = normal_histogram(top, normals, params).reshape(params.shape)
    assert h.size == 800
    filled = h >= 0
    assert set(np.nonzero(filled)[1]) == {14}  # 0.72 m → height bin 14
    assert np.all(h[filled] > 0.9)  # horizontal surface: v_p near 1 (equation 3-1)
    assert np.all(h[~filled] == -1)


def test_orientation_features_point_to_the_camera():
    params = FeatureParams()
    back = np.array([(2.0, y, z) for y in np.arange(-0.3, 0.3, 0.02) for z in np.arange(0.45, 0.9, 0.02)])
    normals = estimate_normals(back, np.array([0.0, 0.0, 1.0]), params)
    q = orientation_features(back, normals, params)
    assert np.nanmax(np.abs(np.abs(q[np.isfinite(q)]) - math.pi)) < 0.1  # facing −x, the camera


def test_shape_descriptor_sees_a_couch_back_along_its_long_side():
    couch = box_points(0.0, 0.0, 0.8, 2.0, 0.0, 0.45)
    back = box_points(-0.3, 0.0, 0.2, 2.0, 0.0, 0.9)
    pts = np.vstack([couch, back])
    normals = estimate_normals(pts, np.array([3.0, 0.0, 1.0]))
    s = shape_descriptor(pts, normals)
    assert s[40] == pytest.approx(0.9, abs=0.03)  # top height
    assert s[44] > 1.8 and s[45] < 0.8  # tall part ~2 m long, item < 0.8 m deep across it


def test_a_walls_remains_beside_its_cleared_columns_leave_the_table_against_it():
    table = box_points(2.0, 0.0, 0.8, 0.8, 0.0, 0.55)
    # a wall 3 cm behind the table, seen to 1.9 m, spread over two cells (as noise does); only
    # the far cells' points reach the top rows of the image, so only they are cleared columns
    wall = np.array([(x, y, z) for x in (2.43, 2.47) for y in np.arange(-1.5, 1.5, 0.02)
                     for z in np.arange(0.0, 1.9, 0.02)])
    pts = np.vstack([table, wall])
    rows = np.full(len(pts), 100.0)
    rows[(pts[:, 0] > 2.45) & (pts[:, 2] > 1.85)] = 0.0  # only the far cells reach the top rows
    samples, _ = extract_samples(pts, rows, image_height=240, params=SampleParams(wall_remains_top_m=None))
    assert len(samples) == 1 and samples[0].height_m > 1.5  # the wall's remains joined the table
    samples, stats = extract_samples(pts, rows, image_height=240)
    assert len(samples) == 1 and samples[0].height_m == pytest.approx(0.55, abs=0.02)
    assert samples[0].footprint_centre_xy == pytest.approx([2.0, 0.0], abs=0.06)


def test_furniture_under_the_wall_remains_height_is_kept_against_a_wall():
    bed = box_points(2.0, 0.0, 2.0, 1.4, 0.0, 0.55)
    headboard = box_points(2.95, 0.0, 0.08, 1.4, 0.0, 1.1)
    wall = np.array([(3.05, y, z) for y in np.arange(-2, 2, 0.02) for z in np.arange(0.0, 2.4, 0.02)])
    samples, _ = extract_samples(np.vstack([bed, headboard, wall]))
    assert len(samples) == 1 and samples[0].height_m == pytest.approx(1.1, abs=0.02)


def test_a_deep_shelf_against_a_wall_keeps_its_tall_part():
    # only the 0.1 m next to the cleared wall is taken as the wall's remains: a 0.4 m deep shelf
    # stays a tall thing without a seat (which the detector drops), not a low bed-like remainder
    shelf = box_points(2.75, 0.0, 0.4, 1.2, 0.0, 1.8)
    wall = np.array([(3.0, y, z) for y in np.arange(-2, 2, 0.02) for z in np.arange(0.0, 2.4, 0.02)])
    samples, _ = extract_samples(np.vstack([shelf, wall]))
    assert len(samples) == 1 and samples[0].height_m == pytest.approx(1.8, abs=0.02)


# ---------------------------------------------------------------- a wall followed down its columns

def _column(readings):
    """(points, rows, cols) of one image column read top to bottom: (range ahead, height)."""
    pts = np.array([(r, 0.0, z) for r, z in readings])
    rows = np.arange(len(pts), dtype=float) * 2.0
    return pts, rows, np.full(len(pts), 100.0)


def test_the_wall_is_followed_down_past_a_picture_and_a_gap_and_ends_at_a_backrest():
    from assistant.perception.samples import wall_continuation

    wall = [(3.0 + 0.002 * (-1) ** i, 2.3 - 0.02 * i) for i in range(40)]  # 2.30 … 1.52 m
    picture = [(2.98, 1.5 - 0.02 * i) for i in range(10)]  # 2 cm nearer, hanging on the wall
    below = [(3.0, 1.2 - 0.02 * i) for i in range(20)]  # after missing readings: 1.20 … 0.82 m
    backrest = [(2.80 - 0.03 * i, 0.7) for i in range(5)] + [(2.65, 0.7 - 0.03 * i) for i in range(8)]
    pts, rows, cols = _column(wall + picture + below + backrest)
    rows[len(wall) + len(picture):] += 40.0  # the gap
    known = pts[:, 2] > 2.0
    out = wall_continuation(pts, rows, cols, known, (0.0, 0.0))
    on_wall = np.zeros(len(pts), dtype=bool)
    on_wall[:len(wall) + len(picture) + len(below)] = True
    assert np.array_equal(out, on_wall & ~known)


def test_the_wall_trace_stops_at_a_table_top_touching_the_wall_and_a_headboard_before_it():
    from assistant.perception.samples import wall_continuation

    wall = [(3.0, 2.3 - 0.02 * i) for i in range(60)]  # down to 1.12 m
    desk = [(2.99 - 0.04 * i, 0.72) for i in range(15)]  # a horizontal top touching the wall
    pts, rows, cols = _column(wall + desk)
    out = wall_continuation(pts, rows, cols, pts[:, 2] > 2.0, (0.0, 0.0))
    assert out[:len(wall)].sum() == (pts[:len(wall), 2] <= 2.0).sum()
    assert not out[len(wall) + 1:].any()  # only the top's edge against the wall is in its band
    headboard = [(2.95, 1.0 - 0.02 * i) for i in range(20)]  # a face 5 cm before the wall
    pts, rows, cols = _column(wall[:45] + headboard)
    out = wall_continuation(pts, rows, cols, pts[:, 2] > 2.0, (0.0, 0.0))
    assert not out[45:].any() and out[16:45].all()


def _against_a_wall(item: str, yaw_deg: float, lean_deg: float = 2.0):
    """A time-of-flight-like frame (512×424, 2 mm noise) of a couch or a bed whose back stands
    5 cm (bed: 3 cm) before an oblique wall leaning ``lean_deg`` away at its top — the floor
    of a real frame is found to a degree or two, and so its walls lean."""
    import open3d as o3d

    from assistant.geometry import Pose2D
    from assistant.perception.database import ItemRenderer
    from assistant.robot.frames import CameraIntrinsics, CameraMount
    from assistant.sim.renderer import KinectNoise

    def box(cx, sx, sy, sz):
        b = o3d.geometry.TriangleMesh.create_box(sx, sy, sz)
        b.translate((cx - sx / 2, -sy / 2, 0.0))
        return b

    if item == "couch":  # seat towards the camera, a 0.7 m back along the far edge
        parts, wall_x = [box(0.0, 0.9, 2.0, 0.42), box(0.55, 0.2, 2.0, 0.7)], 0.7
    else:  # a bed, its 1 m headboard at the far end
        parts, wall_x = [box(0.0, 2.0, 1.4, 0.55), box(1.03, 0.06, 1.4, 1.0)], 1.09
    wall = box(0.05, 0.1, 6.0, 2.6)
    wall.rotate(o3d.geometry.get_rotation_matrix_from_xyz((0.0, math.radians(lean_deg), 0.0)),
                center=(0.0, 0.0, 0.0))
    wall.translate((wall_x, 0.0, 0.0))
    mesh = o3d.geometry.TriangleMesh()
    for part in [*parts, wall]:
        mesh += part
    noise = KinectNoise(sigma_base_m=0.002, sigma_quad_m=0.0, quantise=False, edge_dropout=0.0)
    renderer = ItemRenderer(mesh, CameraIntrinsics(512, 424, 365.0, 365.0, 256.0, 212.0),
                            CameraMount(height_m=1.2, tilt_rad=math.radians(10.0)), noise)
    return renderer.render(Pose2D(2.6, 0.0, math.radians(yaw_deg)), seed=1)


@pytest.mark.parametrize("yaw_deg", [-35.0, 35.0])
def test_a_leaning_walls_lower_part_does_not_stand_on_the_couch_before_it(yaw_deg):
    from assistant.perception.frame import FrameParams, analyse_frame

    frame = _against_a_wall("couch", yaw_deg)
    without = analyse_frame(frame, FrameParams(samples=SampleParams(wall_trace_band_m=None)))
    assert len(without.samples) == 1 and without.samples[0].height_m > 1.0  # the wall's remains
    found = analyse_frame(frame)
    assert found.stats["wall_points"] > 1000
    assert len(found.samples) == 1 and found.samples[0].height_m == pytest.approx(0.7, abs=0.03)


@pytest.mark.parametrize("yaw_deg", [-35.0, 35.0])
def test_a_headboard_before_a_leaning_wall_is_kept(yaw_deg):
    from assistant.perception.frame import analyse_frame

    found = analyse_frame(_against_a_wall("bed", yaw_deg))
    assert len(found.samples) == 1 and found.samples[0].height_m == pytest.approx(1.0, abs=0.03)
    assert float(np.percentile(found.samples[0].points[:, 2], 99)) > 0.95


def test_the_kinect_v2_living_rooms_wall_does_not_stand_on_its_couch(shared_dir):
    """The real frame the trace was made for: without it the L-shaped couch's sample holds the
    wall behind it up to ~1 m (at its 99th percentile), with it only the couch (~0.7 m)."""
    from assistant.perception.depthfile import load_depth_png
    from assistant.perception.frame import FrameParams, analyse_frame
    from assistant.perception.realdata import FOLDERS

    files, k, scale, invalid, _ = FOLDERS["kinect2_livingroom_esanet"]
    path = shared_dir / "realdata" / "kinect2_livingroom_esanet" / files[0]
    if not path.exists():
        pytest.skip(f"{path} not present")
    frame, _ = load_depth_png(path, k, scale, invalid_values=invalid)
    frame.depth_m[frame.depth_m < 0.5] = 0.0

    def couch_top(params):
        found = analyse_frame(frame, params, use_mount=False)
        biggest = max(found.samples, key=lambda s: len(s.cells_xy_m))
        return float(np.percentile(biggest.points[:, 2], 99))

    assert couch_top(FrameParams(samples=SampleParams(wall_trace_band_m=None))) > 0.9
    assert couch_top(FrameParams()) < 0.8


def _l_of_two_couches(yaw_deg: float):
    """Two 2.0 × 0.8 m couches meeting at a corner (an L), turned by ``yaw_deg`` about (2.5, 0)."""
    a = box_points(2.5, -0.6, 0.8, 2.0, 0.0, 0.9)         # along y
    b = box_points(2.9 + 0.6, 0.8, 2.0, 0.8, 0.0, 0.9)   # along x, touching a's end
    pts = np.vstack([a, b])
    t = math.radians(yaw_deg)
    c, s = math.cos(t), math.sin(t)
    xy = (pts[:, :2] - [2.5, 0.0]) @ np.array([[c, s], [-s, c]]) + [2.5, 0.0]
    return np.column_stack([xy, pts[:, 2]])


@pytest.mark.parametrize("yaw_deg", [0.0, 20.0, 45.0])
def test_two_couches_touching_in_an_l_are_two_samples(yaw_deg):
    samples, stats = extract_samples(_l_of_two_couches(yaw_deg))
    assert stats["split"] == 1 and len(samples) == 2
    areas = [len(s.cells_xy_m) * SampleParams().grid_m ** 2 for s in samples]
    assert all(0.6 < a < 2.4 for a in areas)  # each most of one couch (1.6 m²; where the corner goes varies)
    t = math.radians(yaw_deg)
    rot = np.array([[math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]])
    truth = (np.array([[2.5, -0.6], [3.5, 0.8]]) - [2.5, 0.0]) @ rot + [2.5, 0.0]
    for s in samples:  # each part is centred on one couch, a different one each
        d = np.hypot(*(truth - s.footprint_centre_xy).T)
        assert d.min() < 0.35
    assert {int(np.argmin(np.hypot(*(truth - s.footprint_centre_xy).T))) for s in samples} == {0, 1}
    # and without splitting they are one
    joined, _ = extract_samples(_l_of_two_couches(yaw_deg), params=SampleParams(split_min_area_m2=None))
    assert len(joined) == 1


@pytest.mark.parametrize("size", [(2.0, 0.8), (2.1, 1.6), (1.0, 0.6)])
def test_one_rectangular_item_is_never_split(size):
    for yaw in (0.0, 30.0):
        pts = box_points(2.5, 0.0, *size, 0.0, 0.6)
        t = math.radians(yaw)
        xy = (pts[:, :2] - [2.5, 0.0]) @ np.array([[math.cos(t), math.sin(t)], [-math.sin(t), math.cos(t)]]) + [2.5, 0.0]
        samples, stats = extract_samples(np.column_stack([xy, pts[:, 2]]))
        assert len(samples) == 1 and stats.get("split", 0) == 0


def test_the_two_couches_of_the_two_bedroom_house_are_seen_as_two():
    # the L of couch_1 and couch_2 in its living room, seen from the meeting room
    from assistant.geometry import Pose2D
    from assistant.perception.frame import analyse_frame
    from assistant.sim.renderer import DepthRenderer
    from assistant.world import load_world

    world = load_world("two-bedrooms-house")
    frame = DepthRenderer(world, "original", seed=0).render(Pose2D(0.5, 4.0, -math.pi / 2))
    samples = analyse_frame(frame).samples
    big = [s for s in samples if len(s.cells_xy_m) * SampleParams().grid_m ** 2 > 0.8]
    assert len(big) == 2
    # in the camera frame (x ahead, y left, camera at the origin looking south): couch_2 lies
    # across the view about 3.5 m ahead, couch_1 along it on the left
    far, near = sorted(big, key=lambda s: -s.footprint_centre_xy[0])
    assert far.footprint_centre_xy[0] == pytest.approx(3.5, abs=0.3)
    assert near.footprint_centre_xy[0] < far.footprint_centre_xy[0] - 1.0


def test_percentiles_are_numpys_bit_for_bit():
    """Issue 20 (speed): the shape descriptor's, the centre's and the regrouping's percentiles
    come from ``features.percentiles`` — numpy's linear percentiles, the same bits, also per
    column — and its covariances from ``features.covariance`` (``np.cov``'s bits)."""
    from assistant.perception.features import covariance, percentiles

    rng = np.random.default_rng(0)
    for n in [*range(1, 40), 257, 1500]:
        a = rng.normal(size=n) * rng.uniform(0.01, 10)
        if n % 3 == 0:
            a = np.round(a, 1)  # ties
        for q in (0, 2, 5, 37.5, 95, 98, 99, 100):
            value = percentiles(a, q)
            assert isinstance(value, float) and value == np.percentile(a, q)
        assert np.array_equal(percentiles(a, (2, 98)), np.percentile(a, [2, 98]))
        if n > 1:
            columns = np.column_stack([a, a[::-1] * 3.0, np.sort(a)])
            assert np.array_equal(percentiles(columns, (2, 95, 98, 99)), np.percentile(columns, [2, 95, 98, 99], axis=0))
            assert np.array_equal(percentiles(columns, 98), np.percentile(columns, 98, axis=0))
            assert np.array_equal(covariance(columns[:, :2].T), np.cov(columns[:, :2].T))


def test_centring_and_the_wall_traces_column_order_are_numpys_bit_for_bit():
    """2 Dec night (speed): ``samples.centred_xy`` is ``xy - xy.mean(axis=0)`` and its mean,
    the same bits, for an (N, 3) cloud and an (N, 2) view; ``samples._column_order`` is
    ``np.lexsort((rows, columns))`` whether or not the rows are in image order."""
    from assistant.perception.samples import _column_order, centred_xy

    rng = np.random.default_rng(2)
    for n in (1, 2, 5, 999, 30_001):
        points = rng.normal(size=(n, 3)) * 2.0 + 1.0
        for cloud in (points, points[:, :2], np.ascontiguousarray(points[::-1])):
            xy, centre = centred_xy(cloud)
            assert np.array_equal(centre, cloud[:, :2].mean(axis=0))
            assert np.array_equal(xy, cloud[:, :2] - cloud[:, :2].mean(axis=0)) and xy.flags.c_contiguous
        assert np.array_equal(centred_xy(points, np.array([0.5, -2.0]))[0], points[:, :2] - [0.5, -2.0])
        columns = rng.integers(0, 730, n)
        for rows in (np.sort(rng.uniform(0, 480, n)), rng.uniform(0, 480, n), np.round(rng.uniform(0, 9, n))):
            order, sorted_columns = _column_order(columns, rows)
            assert np.array_equal(order, np.lexsort((rows, columns)))
            assert np.array_equal(sorted_columns, columns[order])
