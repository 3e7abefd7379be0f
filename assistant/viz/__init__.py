"""The 3D scene view (meshcat) shared by the command line and notebooks.

``SceneView`` draws a world (room floors, walls, furniture, objects, the robot), point clouds,
paths, score-map arrows and highlights, serves them live in a browser and writes them as one
self-contained HTML page. See ``docs/scene_view.md``.
"""

import warnings

with warnings.catch_warnings():  # meshcat 0.3.2 imports pyzmq's deprecated zmq.eventloop.ioloop
    warnings.simplefilter("ignore", DeprecationWarning)
    import meshcat  # noqa: F401

from assistant.viz.clouds import HIT_COLOURS, depth_frame_points
from assistant.viz.colours import CATEGORY_COLOURS, room_colour, score_colours, to_hex_int, to_rgb
from assistant.viz.detections import draw_detection_result
from assistant.viz.html import external_urls, scene_html
from assistant.viz.labels import label_object, text_png
from assistant.viz.scene_view import SceneView, path_name
from assistant.viz.server import MeshcatServer, ViewerError

__all__ = [
    "CATEGORY_COLOURS", "HIT_COLOURS", "MeshcatServer", "SceneView", "ViewerError",
    "depth_frame_points", "draw_detection_result",
    "external_urls", "label_object", "path_name", "room_colour", "scene_html", "score_colours",
    "text_png", "to_hex_int", "to_rgb",
]
