"""Small objects (mug, laptop, glasses case …): one detector interface, and its simulator model.

Furniture is perceived from depth (:mod:`assistant.perception.detector`); a mug on a table is
too small for that, so small objects are reported by an *object detector* behind the
:class:`ObjectDetector` interface. On hardware a real detector (an RGB network, fiducial
tags …) plugs in here. In the simulator the detector is a sensor model built on the renderer's
hit ids: an object counts as seen when at least ``min_pixels`` of its pixels are in view at a
median depth of at most ``max_range_m``, and each such sighting is dropped with probability
``miss_rate`` (seeded), so that search and memory are exercised against misses.

A sighting carries the object's position in the world frame (the mean of its pixels' 3D
points, metres), computed from the depth frame and the robot pose the frame was taken at.
"""

from __future__ import annotations

import dataclasses
from typing import Iterable, Protocol, runtime_checkable

import numpy as np

from assistant.geometry import Pose2D
from assistant.robot.frames import DepthFrame, camera_to_world_matrix, pixel_rays

__all__ = ["ObjectDetector", "SimObjectDetector", "Sighting"]


@dataclasses.dataclass(frozen=True)
class Sighting:
    """One object seen: the one sighting type of the product, from the detector to the memory.

    The detector fills ``x_m``/``y_m``/``z_m`` (world-frame position of the object's visible
    surface: the mean of its pixels' points), ``distance_m`` (median depth of its pixels),
    ``pixels`` (how many) and ``timestamp_s`` (the frame's robot-clock time stamp). A task
    *places* it (:func:`assistant.executor.sightings.place_sightings`): ``room`` (floor-plan
    room name) and the perceived furniture it lies on (``furniture_id`` /
    ``furniture_category``, None when on nothing the robot has found); a search adds
    ``seen_from``, the robot pose of the frame. A sighting read from a world file (the oracle
    search) has no pixels and distance 0.
    """

    name: str
    x_m: float
    y_m: float
    z_m: float = 0.0
    distance_m: float = 0.0
    pixels: int = 0
    timestamp_s: float = 0.0
    room: str | None = None
    furniture_id: str | None = None
    furniture_category: str | None = None
    seen_from: Pose2D | None = None

    def to_dict(self) -> dict:
        out = {"name": self.name, "x": round(self.x_m, 3), "y": round(self.y_m, 3),
               "z": round(self.z_m, 3), "distance": round(self.distance_m, 3),
               "pixels": self.pixels, "timestamp": round(self.timestamp_s, 3),
               "room": self.room, "furniture_id": self.furniture_id, "furniture": self.furniture_category}
        if self.seen_from is not None:
            p = self.seen_from
            out["seen_from"] = [p.x, p.y, p.theta]
        return out


@runtime_checkable
class ObjectDetector(Protocol):
    """Anything that reports the small objects visible in a depth (or RGB-D) frame.

    A detector may also have ``reads(frame) -> bool``: whether it can tell anything from that
    frame at all (False: an empty :meth:`detect` means "cannot tell", not "nothing there"); the
    fetch task asks it before searching other surfaces for an object it did not see.
    """

    def detect(self, frame: DepthFrame) -> list[Sighting]: ...


class SimObjectDetector:
    """The simulator's object detector: reads the renderer's hit ids (never used on hardware).

    ``names``: the object names it can recognise (for example ``[o.name for o in
    scene.objects]``); ids of other things (floor, walls, furniture) are ignored.
    ``min_pixels``: pixels of an object needed to count it as seen (640×480 frame).
    ``max_range_m``: largest median depth at which it is still recognised.
    ``miss_rate``: probability in [0, 1) that a visible object is not reported in a frame.
    ``seed``: seeds the misses, so a run is repeatable.
    """

    def __init__(self, names: Iterable[str], min_pixels: int = 50, max_range_m: float = 4.5,
                 miss_rate: float = 0.0, seed: int = 0):
        if not 0.0 <= miss_rate < 1.0:
            raise ValueError(f"miss_rate must be in [0, 1), got {miss_rate}")
        if min_pixels < 1:
            raise ValueError(f"min_pixels must be at least 1, got {min_pixels}")
        self.names = frozenset(names)
        self.min_pixels = int(min_pixels)
        self.max_range_m = float(max_range_m)
        self.miss_rate = float(miss_rate)
        self.seed = seed
        self._rng = np.random.default_rng(seed)

    @classmethod
    def for_scene(cls, scene, **params) -> "SimObjectDetector":
        """A detector for the objects placed in a :class:`~assistant.world.Scene`."""
        return cls([obj.name for obj in scene.objects], **params)

    def reads(self, frame: DepthFrame) -> bool:
        """Only the simulator's own frames (with hit ids): a replayed or real frame tells it nothing."""
        return frame.hit_ids is not None

    def detect(self, frame: DepthFrame) -> list[Sighting]:
        """The recognisable objects in ``frame``; empty when the frame has no hit ids (a real
        camera's frame: use a real detector there)."""
        if frame.hit_ids is None or not self.names:
            return []
        valid = frame.depth_m > 0
        ids = frame.hit_ids
        present = np.unique(ids[valid & (ids >= 0)])
        sightings = []
        rays = None
        to_world = None
        for index in present:
            name = frame.hit_names[int(index)]
            if name not in self.names:
                continue
            mask = (ids == index) & valid
            pixels = int(mask.sum())
            if pixels < self.min_pixels:
                continue
            depth = frame.depth_m[mask].astype(np.float64)
            distance = float(np.median(depth))
            if distance > self.max_range_m:
                continue
            if self.miss_rate > 0.0 and self._rng.random() < self.miss_rate:
                continue
            if rays is None:
                rays = pixel_rays(frame.intrinsics)
                # a frame without a robot pose (read from disk) gives positions in the robot's frame
                to_world = camera_to_world_matrix(frame.mount, frame.robot_pose or Pose2D(0.0, 0.0, 0.0))
            points = rays[mask].astype(np.float64) * depth[:, None]
            world = points @ to_world[:3, :3].T + to_world[:3, 3]
            x, y, z = world.mean(axis=0)
            sightings.append(Sighting(name, float(x), float(y), float(z), distance, pixels,
                                      float(frame.timestamp_s)))
        return sorted(sightings, key=lambda s: s.name)
