"""A matplotlib animation as an HTML player that needs no other host and says what it shows.

matplotlib's ``Animation.to_jshtml`` writes a player whose buttons are Font Awesome icons from a
content delivery network (a stylesheet link to ``maxcdn.bootstrapcdn.com``), whose picture has
no text alternative and whose frame slider has no label. :func:`animation_html` takes that
player and makes three changes, so that it works offline in JupyterLab and on the course
website and reads well with a screen reader:

* the remote stylesheet is dropped and each icon becomes a plain Unicode symbol (the buttons
  keep matplotlib's names, such as "Play" and "Next frame", as their labels);
* the picture gets the text alternative ``alt``;
* the slider gets the label "Frame".

Examples
--------
>>> html = _offline_player(
...     '<link rel="stylesheet"\\nhref="https://cdn.example/font-awesome.min.css">\\n'
...     '<img id="_anim_img1"><input id="_anim_slider1" type="range">'
...     '<button title="Play"><i class="fa fa-play"></i></button>',
...     alt="A ring tips over.",
... )
>>> "cdn" in html, 'alt="A ring tips over."' in html, 'aria-label="Frame"' in html
(False, True, True)
>>> ">▶<" in html
True
"""

from __future__ import annotations

import html as html_text
import re
from typing import Any

__all__ = ["animation_html"]

_REMOTE_STYLESHEET = re.compile(r"<link\b[^>]*\bhref=[\"']https?://[^\"']*[\"'][^>]*>\s*")
#: matplotlib's icons (``fa-...`` classes of Font Awesome 4) and the symbols that replace them.
_SYMBOLS = {
    "fa fa-minus": "−",
    "fa fa-fast-backward": "⏮",
    "fa fa-step-backward": "⏴",
    "fa fa-play fa-flip-horizontal": "◀",
    "fa fa-pause": "⏸",
    "fa fa-play": "▶",
    "fa fa-step-forward": "⏵",
    "fa fa-fast-forward": "⏭",
    "fa fa-plus": "+",
}
_ICON = re.compile(r'<i class="(fa [^"]+)"></i>')


def _offline_player(player: str, *, alt: str) -> str:
    """The changes of :func:`animation_html`, on the HTML that ``to_jshtml`` wrote."""
    page = _REMOTE_STYLESHEET.sub("", player)

    def symbol(match: re.Match[str]) -> str:
        shown = _SYMBOLS.get(match.group(1), "•")
        return f'<span aria-hidden="true">{shown}</span>'

    page = _ICON.sub(symbol, page)
    page = re.sub(
        r'<img id="(_anim_img\w*)"',
        lambda m: f'<img id="{m.group(1)}" alt="{html_text.escape(alt)}"',
        page,
        count=1,
    )
    return re.sub(
        r'<input id="(_anim_slider\w*)"',
        lambda m: f'<input id="{m.group(1)}" aria-label="Frame"',
        page,
        count=1,
    )


def animation_html(animation: Any, *, alt: str, fps: float | None = None) -> str:
    """An animation as an HTML player that fetches nothing from another host.

    Parameters
    ----------
    animation : matplotlib.animation.Animation
        The animation, for example from ``eulerlib.plotting.animate_gimbal_lock``.
    alt : str
        What the animation shows, in a sentence or two: the player's text alternative.
    fps : float, optional
        Frames per second, as for ``Animation.to_jshtml``.

    Returns
    -------
    str
        HTML for ``IPython.display.HTML``: matplotlib's player with Unicode symbols for its
        buttons, ``alt`` on its picture and a label on its slider.

    Raises
    ------
    ValueError
        If ``alt`` is empty.
    """
    if not isinstance(alt, str) or not alt.strip():
        raise ValueError("alt must say what the animation shows, in words")
    return _offline_player(str(animation.to_jshtml(fps=fps)), alt=alt.strip())
