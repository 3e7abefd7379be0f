"""Scoring the detector on real depth frames from a folder a user gives (``--realdata PATH``).

The product never ships these files; it reads them in place. ``--realdata PATH`` is a folder
of sub-folders (or one such sub-folder), each holding depth PNGs and their labels in one of three
label layouts: ``sun`` (SUN RGB-D: ``<id>_boxes.json`` with 3D boxes and the gravity frame
``Rtilt``, optionally ``<id>_boxmask.png``), ``boxes2d`` (``annotations_visual.json``: 2D boxes
with a category each) and ``negative`` (no furniture near the camera: every bed or couch is
false). A sub-folder says how to read it in a ``frames.json`` (:func:`folder_spec`): its depth
files, intrinsics, metres per depth unit, invalid raw values, label layout and the nearest
valid depth. The five folders of ``../shared/realdata`` need none: their layouts are known
here (:data:`FOLDERS`). docs/perception.md says how to add frames of other public datasets.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

#: folder → (depth files, (fx, fy, cx, cy), metres per unit, invalid raw values, labels)
FOLDERS = {
    "sunrgbd_kv2_mmdet3d": ([f"00000{i}_depth.png" for i in range(1, 5)], (529.5, 529.5, 364.0, 264.0),
                            1e-3, (65535,), "sun"),
    "nyu_livingroom_unidepth": (["depth.png"], (518.8579, 519.4696, 325.5825, 253.7362), 1e-3,
                                (10000, 65535), "boxes2d"),
    "kinect2_livingroom_esanet": (["sample_depth.png"], (365.0, 365.0, 256.0, 212.0), 1e-4,
                                  (65535,), "boxes2d"),
    "tum_office_open3d": (["TUM_depth.png"], (525.0, 525.0, 319.5, 239.5), 2e-4, (65535,), "boxes2d"),
    "nyu_basement_metric3d": ([f"sync_depth_{i}.png" for i in ("00000", "00050", "00100")],
                              (518.8579, 519.4696, 325.5825, 253.7362), 1e-3, (65535,), "negative"),
}
LABELS = ("sun", "boxes2d", "negative", "none")
#: known folders whose nearest valid reading is not the sensor's (the Kinect v2 frame's flying
#: pixels under 0.5 m, as its README says)
MIN_DEPTH_M = {"kinect2_livingroom_esanet": 0.5}
SUN_CATEGORY = {"bed": "bed", "night_stand": "small table"}
#: a labelled object with less than this share of its depth pixels inside the detector's
#: sample range (``SampleParams.max_forward_m`` ahead) is reported as out of range
IN_RANGE_SHARE = 0.5


def _floor_to_camera(floor, xyz: np.ndarray) -> np.ndarray:
    m = floor.camera_to_floor
    return (np.atleast_2d(xyz) - m[:3, 3]) @ m[:3, :3]


def folder_spec(folder: Path) -> dict | None:
    """How to read a folder of real frames: {"frames": [depth PNG names], "intrinsics": [fx, fy,
    cx, cy] (pixels, 0-based), "depth_scale_m": metres per unit, "invalid": [raw values that
    mean no reading], "labels": one of :data:`LABELS`, "min_depth_m": nearer readings are
    dropped (0)} — from its ``frames.json`` if it has one, else from :data:`FOLDERS` by its
    name; None for a folder that is neither. A bad ``frames.json`` raises
    :class:`~assistant.errors.DataFileError` naming the field."""
    from assistant.errors import DataFileError

    manifest = folder / "frames.json"
    if manifest.exists():
        try:
            data = json.loads(manifest.read_text(encoding="utf-8"))
            spec = {"frames": [str(f) for f in data["frames"]],
                    "intrinsics": tuple(float(v) for v in data["intrinsics"]),
                    "depth_scale_m": float(data["depth_scale_m"]),
                    "invalid": tuple(int(v) for v in data.get("invalid", (65535,))),
                    "labels": str(data.get("labels", "none")),
                    "min_depth_m": float(data.get("min_depth_m", 0.0))}
        except (ValueError, KeyError, TypeError) as exc:
            raise DataFileError(str(manifest), "frames.json", f"needs frames, intrinsics (fx, fy, cx, cy) and "
                                f"depth_scale_m ({type(exc).__name__}: {exc})") from None
        if len(spec["intrinsics"]) != 4 or spec["labels"] not in LABELS:
            raise DataFileError(str(manifest), "intrinsics/labels",
                                f"4 intrinsics and labels one of {', '.join(LABELS)}")
        return spec
    if folder.name in FOLDERS:
        files, k, scale, invalid, labels = FOLDERS[folder.name]
        return {"frames": files, "intrinsics": k, "depth_scale_m": scale, "invalid": invalid,
                "labels": labels, "min_depth_m": MIN_DEPTH_M.get(folder.name, 0.0)}
    return None


def real_folders(root: str | Path) -> dict[str, dict]:
    """Folder name → :func:`folder_spec` of every readable folder of real frames: ``root``
    itself if it is one, else its sub-folders (sorted; known folders in :data:`FOLDERS` order)."""
    root = Path(root)
    if (spec := folder_spec(root)) is not None and (root / "frames.json").exists():
        return {root.name: {**spec, "path": root}}
    subs = sorted((p for p in root.iterdir() if p.is_dir()), key=lambda p: (
        list(FOLDERS).index(p.name) if p.name in FOLDERS else len(FOLDERS), p.name)) if root.is_dir() else []
    return {p.name: {**spec, "path": p} for p in subs if (spec := folder_spec(p)) is not None}


def load_frames(root: str | Path):
    """``(folder, file name, DepthFrame)`` of every real frame of :func:`real_folders` that
    exists, read with its folder's depth units, intrinsics, invalid values and nearest depth."""
    for folder, spec in real_folders(root).items():
        for name in spec["frames"]:
            path = spec["path"] / name
            if path.exists():
                yield folder, name, load_real_frame(path, spec)


def load_real_frame(path: str | Path, spec: dict):
    """One depth PNG read as :func:`folder_spec` ``spec`` says: its intrinsics, metres per unit,
    invalid raw values, and readings nearer than ``min_depth_m`` dropped."""
    from assistant.perception.depthfile import load_depth_png

    frame, _ = load_depth_png(path, spec["intrinsics"], spec["depth_scale_m"], invalid_values=spec["invalid"])
    if spec.get("min_depth_m", 0.0) > 0:
        frame.depth_m[frame.depth_m < spec["min_depth_m"]] = 0.0
    return frame


def evaluate_realdata(root: str | Path, detector) -> dict:
    """Per folder and frame: the floor, the detections, and the scores its labels allow."""
    root = Path(root)
    folders = real_folders(root)
    out: dict = {"root": str(root), "folders": {f: [] for f in folders}}
    for folder, name, frame in load_frames(root):
        base, labels = folders[folder]["path"], folders[folder]["labels"]
        result = detector.analyse(frame, use_mount=False)
        entry = {"file": name, "floor": result.floor.to_dict() if result.floor else None,
                 "detections": [d.to_dict() for d in result.detections],
                 "unknown": [u.to_dict() for u in result.unknown],
                 "reason": result.reason, "ms": round(result.timings_ms.get("total", 0.0), 1)}
        if labels == "sun":
            entry.update(_score_sun(base, name.removesuffix(".png").removesuffix("_depth"), result, frame,
                                    detector.params.samples.max_forward_m))
        elif labels == "boxes2d":
            entry.update(_score_boxes(base, result, frame))
        elif labels == "negative":
            entry["false_beds_or_couches"] = sum(d.category in ("bed", "couch") for d in result.detections)
        out["folders"][folder].append(entry)
    out["summary"] = summarise(out)
    return out


def summarise(report: dict) -> dict:
    """The issue's real-frame checks counted over every frame: floors found; labelled beds,
    couches and night stands detected as such (SUN beds also among those with most of their
    pixels inside the sample range; one mostly beyond the range and reported as a partial item
    of its category — cut by the range or the image — is counted apart, in
    ``out_of_range_partial``, not in ``correct``); beds or couches where none is labelled — in the negative
    frames, and elsewhere (a detection that no labelled bed or couch took)."""
    frames = [f for fs in report["folders"].values() for f in fs]
    s = {"frames": len(frames), "floor_found": sum(f["floor"] is not None for f in frames)}
    tally: dict = {}

    def count(what: str, correct: bool, in_range: bool = True, partial: bool = False) -> None:
        t = tally.setdefault(what, {"correct": 0, "labelled": 0, "in_range_correct": 0,
                                    "in_range": 0, "out_of_range_partial": 0})
        t["labelled"] += 1
        t["correct"] += bool(correct and not (partial and not in_range))  # seen whole enough
        t["in_range"] += bool(in_range)
        t["in_range_correct"] += bool(correct and in_range)
        t["out_of_range_partial"] += bool(correct and partial and not in_range)

    false_elsewhere = 0
    for f in frames:
        taken: set[int] = set()
        for m in f.get("matches", []):
            count(m["object"], m["correct"], m.get("in_range_share", 1.0) >= IN_RANGE_SHARE,
                  m.get("partial", False))
            if m.get("detection") is not None and m["correct"]:
                taken.add(m["detection"])
        for b in f.get("boxes", []):
            if b["object"] in ("couch", "bed", "chair", "large_table", "small_table"):
                count(b["object"], b["correct"])
            if b["object"] in ("couch", "bed"):
                taken.update(i for i, c in zip(b.get("detection_indices", []), b["detected"])
                             if c == b["object"].replace("_", " "))
        if "false_beds_or_couches" not in f:
            false_elsewhere += sum(d["category"] in ("bed", "couch") and i not in taken
                                   for i, d in enumerate(f["detections"]))
    s["labelled"] = tally
    s["false_beds_or_couches_in_negatives"] = sum(f.get("false_beds_or_couches", 0) for f in frames)
    s["false_beds_or_couches_elsewhere"] = false_elsewhere
    return s


def _score_sun(base: Path, frame_id: str, result, frame, range_m: float) -> dict:
    """Floor vs Rtilt; each labelled bed / night stand matched to the nearest detection, with
    the share of its box-mask pixels (``_boxmask.png``) less than ``range_m`` ahead of the
    camera in the floor frame the detector found — the points the detector can use."""
    data = json.loads((base / f"{frame_id}_boxes.json").read_text())
    rtilt = np.asarray(data["Rtilt"], dtype=float)
    up_cam = np.array([rtilt[2, 0], -rtilt[2, 2], rtilt[2, 1]])  # upright z in camera axes
    score: dict = {"truth_camera_height": data.get("camera_height_above_floor_m_estimate")}
    floor = result.floor
    if floor is None:
        return score
    score["floor_normal_error_deg"] = round(math.degrees(math.acos(
        min(1.0, abs(float(up_cam @ floor.normal_camera))))), 2)

    def to_upright(p_cam: np.ndarray) -> np.ndarray:
        p = np.atleast_2d(p_cam)
        return np.column_stack([p[:, 0], p[:, 2], -p[:, 1]]) @ rtilt.T

    in_range = _in_range_shares(base / f"{frame_id}_boxmask.png", frame, floor, range_m)
    dets = []
    for i, d in enumerate(result.detections):
        centre = to_upright(_floor_to_camera(floor, np.array([d.x, d.y, d.height_m / 2])))[0]
        yaw = None
        if d.facing is not None:
            tip = np.array([d.x + math.cos(d.facing), d.y + math.sin(d.facing), d.height_m / 2])
            v = to_upright(_floor_to_camera(floor, tip))[0] - centre
            yaw = math.atan2(v[1], v[0])
        dets.append((d, centre, yaw, i))
    matches = []
    for obj in data["objects"]:
        wanted = SUN_CATEGORY.get(obj["sun_class"])
        if wanted is None:
            continue
        gt = np.asarray(obj["center_upright_m"][:2])
        best = min(dets, key=lambda t: np.linalg.norm(t[1][:2] - gt), default=None)
        if best is not None and np.linalg.norm(best[1][:2] - gt) >= 1.0:
            best = _seen_part_on(obj, dets, floor, to_upright) or best
        row = {"object": obj["sun_class"], "expected": wanted,
               "pixels": obj["n_valid_depth_pixels_inside_box"],
               "hard": obj["n_valid_depth_pixels_inside_box"] < 2000}
        if obj["index"] in in_range:
            row["in_range_share"] = in_range[obj["index"]]
        if best is not None and np.linalg.norm(best[1][:2] - gt) < 1.0:
            d, centre, yaw, index = best
            row.update({"detected": d.category, "detection": index, "correct": d.category == wanted,
                        "partial": bool(d.partial or d.beyond_range),
                        "position_error_m": round(float(np.linalg.norm(centre[:2] - gt)), 3)})
            if yaw is not None and wanted == "bed":
                err = abs((yaw - obj["yaw_upright_rad"] + math.pi) % (2 * math.pi) - math.pi)
                row["orientation_error_deg"] = round(math.degrees(err), 1)
        else:
            row.update({"detected": None, "correct": False})
        matches.append(row)
    score["matches"] = matches
    return score


def _seen_part_on(obj: dict, dets: list, floor, to_upright, min_share: float = 0.5):
    """The detection cut by the range or the image (``beyond_range`` or ``partial``) with the
    largest share (at least ``min_share``) of its floor cells inside the labelled box's
    footprint, or None: a partial view shows the item's near end, whose centre can lie a metre
    or more from the box's (SUN 000001's bed, seen from its foot end)."""
    from assistant.geometry import point_in_polygon

    corners = obj.get("corners_upright_m")
    if not corners:
        return None
    footprint = np.asarray(corners, dtype=float)[:4, :2]
    best, best_share = None, min_share
    for entry in dets:
        d = entry[0]
        if not (d.partial or d.beyond_range) or d.frame != "camera-floor" or not len(d.cells_xy):
            continue
        cells = np.column_stack([d.cells_xy, np.zeros(len(d.cells_xy))])
        share = float(np.mean(point_in_polygon(to_upright(_floor_to_camera(floor, cells))[:, :2], footprint)))
        if share >= best_share:
            best, best_share = entry, share
    return best


def _in_range_shares(mask_path: Path, frame, floor, range_m: float) -> dict[int, float]:
    """Box index → share (0–1) of that box's mask pixels less than ``range_m`` ahead (floor
    frame x); {} without a mask file."""
    if not mask_path.exists():
        return {}
    from PIL import Image

    mask = np.asarray(Image.open(mask_path))
    depth = np.asarray(frame.depth_m)
    if mask.shape != depth.shape:
        return {}
    k = frame.intrinsics
    v, u = np.nonzero((mask > 0) & np.isfinite(depth) & (depth > 0))
    z = depth[v, u]
    cam = np.column_stack([(u - k.cx) * z / k.fx, (v - k.cy) * z / k.fy, z])
    m = floor.camera_to_floor
    ahead = cam @ m[0, :3] + m[0, 3]
    labels = mask[v, u]
    return {int(i): round(float(np.mean(ahead[labels == i] < range_m)), 3) for i in np.unique(labels)}


def _score_boxes(base: Path, result, frame) -> dict:
    """Each labelled 2D box gets the category of every detection whose vertical axis (the
    centre, from the floor to its top, in 0.1 m steps) projects into it: a box drawn by eye
    around a couch need not hold the projection of its mid-height, which flying pixels above
    the back can push up."""
    data = json.loads((base / "annotations_visual.json").read_text())
    k = frame.intrinsics
    floor = result.floor
    projected = []
    if floor is not None:
        for i, d in enumerate(result.detections):
            heights = np.append(np.arange(0.05, max(d.height_m, 0.1), 0.1), d.height_m)
            axis = np.column_stack([np.full(len(heights), d.x), np.full(len(heights), d.y), heights])
            p = _floor_to_camera(floor, axis)
            p = p[p[:, 2] > 0.1]
            projected.append((i, d, k.fx * p[:, 0] / p[:, 2] + k.cx, k.fy * p[:, 1] / p[:, 2] + k.cy))
    rows = []
    for obj in data["objects"]:
        x0, y0, x1, y1 = obj["bbox2d"]
        inside = [(i, d) for i, d, u, v in projected
                  if np.any((x0 <= u) & (u <= x1) & (y0 <= v) & (v <= y1))]
        expected = obj["category"].replace("_", " ")
        rows.append({"object": obj["category"], "detected": [d.category for _, d in inside],
                     "detection_indices": [i for i, _ in inside],
                     "correct": any(d.category == expected for _, d in inside)})
    return {"boxes": rows}
