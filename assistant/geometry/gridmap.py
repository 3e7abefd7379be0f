"""A 2D grid over the floor: resolution, origin, and world ↔ cell conversion.

Cells are indexed ``[iy, ix]``: the column index ``ix`` grows with +x, the row index ``iy``
with +y. The origin is the world position (metres) of the *corner* of cell ``[0, 0]``; the
centre of cell ``[iy, ix]`` is ``origin + (ix + 0.5, iy + 0.5) * resolution``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class GridMap:
    """Geometry of a floor grid (no data: masks and costs are arrays of :attr:`shape`)."""

    resolution_m: float
    origin_x_m: float
    origin_y_m: float
    width_cells: int
    height_cells: int

    def __post_init__(self) -> None:
        if not (self.resolution_m > 0 and math.isfinite(self.resolution_m)):
            raise ValueError(f"grid resolution must be a positive number of metres, got {self.resolution_m}")
        if self.width_cells <= 0 or self.height_cells <= 0:
            raise ValueError(f"grid must have at least one cell, got {self.width_cells}×{self.height_cells}")

    @classmethod
    def covering(cls, xmin: float, ymin: float, xmax: float, ymax: float,
                 resolution_m: float, margin_m: float = 0.0) -> "GridMap":
        """The smallest grid of ``resolution_m`` cells covering a box (plus ``margin_m``),
        with its origin snapped to a multiple of the resolution so grids of the same
        resolution line up cell for cell."""
        x0 = math.floor((xmin - margin_m) / resolution_m + 1e-9) * resolution_m
        y0 = math.floor((ymin - margin_m) / resolution_m + 1e-9) * resolution_m
        nx = max(1, math.ceil((xmax + margin_m - x0) / resolution_m - 1e-9))
        ny = max(1, math.ceil((ymax + margin_m - y0) / resolution_m - 1e-9))
        return cls(resolution_m, x0, y0, nx, ny)

    @property
    def shape(self) -> tuple[int, int]:
        """``(height_cells, width_cells)``, the shape of arrays over this grid."""
        return (self.height_cells, self.width_cells)

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` in metres."""
        return (
            self.origin_x_m,
            self.origin_y_m,
            self.origin_x_m + self.width_cells * self.resolution_m,
            self.origin_y_m + self.height_cells * self.resolution_m,
        )

    def world_to_cell(self, points_xy: np.ndarray) -> np.ndarray:
        """(N, 2) world points (metres) → (N, 2) integer cells ``(iy, ix)`` (may be outside)."""
        pts = np.asarray(points_xy, dtype=float).reshape(-1, 2)
        ix = np.floor((pts[:, 0] - self.origin_x_m) / self.resolution_m).astype(int)
        iy = np.floor((pts[:, 1] - self.origin_y_m) / self.resolution_m).astype(int)
        return np.stack([iy, ix], axis=1)

    def cell_to_world(self, cells_iy_ix: np.ndarray) -> np.ndarray:
        """(N, 2) cells ``(iy, ix)`` → (N, 2) world points at the cell centres (metres)."""
        cells = np.asarray(cells_iy_ix, dtype=float).reshape(-1, 2)
        x = self.origin_x_m + (cells[:, 1] + 0.5) * self.resolution_m
        y = self.origin_y_m + (cells[:, 0] + 0.5) * self.resolution_m
        return np.stack([x, y], axis=1)

    def contains_cells(self, cells_iy_ix: np.ndarray) -> np.ndarray:
        cells = np.asarray(cells_iy_ix).reshape(-1, 2)
        return (
            (cells[:, 0] >= 0) & (cells[:, 0] < self.height_cells)
            & (cells[:, 1] >= 0) & (cells[:, 1] < self.width_cells)
        )

    def cell_centres(self) -> tuple[np.ndarray, np.ndarray]:
        """Two arrays of :attr:`shape`: the x and y (metres) of every cell centre."""
        xs = self.origin_x_m + (np.arange(self.width_cells) + 0.5) * self.resolution_m
        ys = self.origin_y_m + (np.arange(self.height_cells) + 0.5) * self.resolution_m
        return np.meshgrid(xs, ys)

    def rasterize_polygon(self, polygon_xy: np.ndarray) -> np.ndarray:
        """Boolean mask of the cells whose centre lies inside a polygon (metres).

        A polygon thinner than a cell still marks the cell(s) under its vertices and edges'
        midpoints, so small objects never vanish from the grid.
        """
        from skimage.draw import polygon2mask  # scikit-image does the scan conversion

        poly = np.asarray(polygon_xy, dtype=float).reshape(-1, 2)
        # skimage wants (row, col) coordinates with pixel centres at integers
        rows = (poly[:, 1] - self.origin_y_m) / self.resolution_m - 0.5
        cols = (poly[:, 0] - self.origin_x_m) / self.resolution_m - 0.5
        mask = polygon2mask(self.shape, np.stack([rows, cols], axis=1))
        if not mask.any():
            samples = np.vstack([poly, (poly + np.roll(poly, -1, axis=0)) / 2, poly.mean(axis=0)])
            cells = self.world_to_cell(samples)
            cells = cells[self.contains_cells(cells)]
            mask[cells[:, 0], cells[:, 1]] = True
        return mask

    def to_dict(self) -> dict[str, float | int]:
        return {
            "resolution_m": self.resolution_m,
            "origin_x_m": self.origin_x_m,
            "origin_y_m": self.origin_y_m,
            "width_cells": self.width_cells,
            "height_cells": self.height_cells,
        }
