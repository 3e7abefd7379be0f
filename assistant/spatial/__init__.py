"""Spatial relations: histograms of forces, spatial relation variables, world state features.

* :func:`histogram_of_forces` — F0 / F2 / F02 of two crisp grid objects (exact for cells).
* :class:`DirSRV`, :class:`DistSRV`, :class:`RotSRV` (:class:`SRV`) — dissertation 5.4.2.
* :class:`WSF`, :class:`WSFBuilder`, :func:`world_state_feature` — dissertation 5.5.1.
* :func:`relations` — furniture pairs of a world file (``assistant relations``).
"""

from assistant.spatial.forces import (
    DEFAULT_DIRECTIONS,
    FORCES,
    direction_angles,
    force_histograms,
    histogram_from_cells,
    histogram_of_forces,
)
from assistant.spatial.relations import relations
from assistant.spatial.srv import (
    DIR_LABELS,
    DIST_LABELS,
    SRV,
    DirSRV,
    DistSRV,
    RotSRV,
    dir_srv,
    direction_word_angles,
    distance_histogram,
    dist_srv,
    rot_srv,
    split_histogram,
)
from assistant.spatial.wsf import ROLES, WSF, WSFBuilder, srv_slots, world_state_feature

__all__ = [
    "DEFAULT_DIRECTIONS", "DIR_LABELS", "DIST_LABELS", "FORCES", "ROLES", "SRV", "WSF",
    "DirSRV", "DistSRV", "RotSRV", "WSFBuilder", "dir_srv", "direction_angles",
    "direction_word_angles", "dist_srv", "distance_histogram", "force_histograms",
    "histogram_from_cells", "histogram_of_forces", "relations", "rot_srv", "split_histogram",
    "srv_slots", "world_state_feature",
]
