"""A self-contained HTML page of a recorded meshcat scene.

The page holds meshcat's viewer script (``viewer/dist/main.min.js`` from the installed meshcat
package, inlined) and the scene as base64 ``data:`` messages, replayed the way
``meshcat-server``'s ``get_scene`` does — so it opens from disk with no server and no network.
The only URL-like strings in it are XML namespace names inside the viewer script (e.g.
``http://www.w3.org/1999/xhtml``), which browsers compare as strings and never fetch, and the
viewer's unused live-connection default ``ws://${location.host}``; :func:`external_urls`
lists anything else.
"""

from __future__ import annotations

import html as html_escape
import re
from functools import lru_cache
from pathlib import Path

from meshcat.servers.tree import walk

__all__ = ["NAMESPACE_URLS", "SAME_HOST_URLS", "external_urls", "scene_html", "viewer_script"]

#: XML namespace names (identifiers, never fetched) that the viewer script contains.
NAMESPACE_URLS = frozenset({
    "http://www.w3.org/1999/xhtml",
    "http://www.w3.org/2000/svg",
    "http://www.w3.org/1998/Math/MathML",
    "http://www.w3.org/1999/xlink",
    "http://www.w3.org/XML/1998/namespace",
    "http://www.w3.org/2000/xmlns/",
})

#: The viewer's ``connect()`` default: a websocket to the page's own host. The static page
#: never calls ``connect()``; the string is a template, not an address on the internet.
SAME_HOST_URLS = frozenset({"ws://${location.host}"})

_URL = re.compile(r"""(?:https?|wss?|ftp)://[^\s"'`<>()\\]+""", re.IGNORECASE)


@lru_cache(maxsize=1)
def viewer_script() -> str:
    """The meshcat viewer's JavaScript bundle shipped with the meshcat package."""
    import meshcat

    path = Path(meshcat.__file__).parent / "viewer" / "dist" / "main.min.js"
    if not path.is_file():
        from assistant.errors import AssistantError

        raise AssistantError(f"meshcat's viewer script is missing ({path}); reinstall meshcat "
                             "with `pip install --force-reinstall meshcat==0.3.2`")
    return path.read_text(encoding="utf-8")


def _command_js(packed: bytes) -> str:
    import base64

    data = base64.b64encode(packed).decode("ascii")
    return (f'viewer.handle_command_bytearray(base64ToBytes("{data}"));\n')


def scene_html(tree, title: str = "Scene") -> str:
    """The HTML page of a meshcat scene tree (``meshcat.servers.tree.SceneTree``).

    Commands are replayed in tree order (objects, then their properties, transforms and
    animations), like ``meshcat-server``'s ``get_scene``; they are decoded synchronously
    so the scene is complete once the page has loaded.
    """
    commands: list[str] = []
    for node in walk(tree):
        if node.object is not None:
            commands.append(_command_js(node.object))
        for prop in node.properties:
            commands.append(_command_js(prop))
        if node.transform is not None:
            commands.append(_command_js(node.transform))
        if node.animation is not None:
            commands.append(_command_js(node.animation))
    script = viewer_script().replace("</script", "<\\/script")
    return f"""<!DOCTYPE html>
<html>
<head>
<meta charset="utf-8">
<meta name="generator" content="assistant.viz (meshcat viewer)">
<title>{html_escape.escape(title)}</title>
<style>
  body {{ margin: 0; }}
  #meshcat-pane {{ width: 100vw; height: 100vh; overflow: hidden; }}
</style>
</head>
<body>
<div id="meshcat-pane"></div>
<script>
{script}
</script>
<script>
function base64ToBytes(text) {{
  var raw = atob(text);
  var bytes = new Uint8Array(raw.length);
  for (var i = 0; i < raw.length; i++) {{ bytes[i] = raw.charCodeAt(i); }}
  return bytes;
}}
var viewer = new MeshCat.Viewer(document.getElementById("meshcat-pane"));
{"".join(commands)}</script>
</body>
</html>
"""


def external_urls(page: str) -> list[str]:
    """URLs in ``page`` a browser could fetch: every ``http(s)``/``ws(s)``/``ftp`` URL except
    the XML namespace names of :data:`NAMESPACE_URLS` and :data:`SAME_HOST_URLS`. Empty for
    a self-contained page."""
    allowed = NAMESPACE_URLS | SAME_HOST_URLS
    return sorted({u for u in _URL.findall(page) if u not in allowed})
