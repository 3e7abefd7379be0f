"""A home-robot assistant directed with ordinary spatial language.

The layers follow ``DESIGN.md``: ``geometry`` and ``world`` at the bottom, then ``sim`` and
``robot`` (adapters), ``perception``, ``language`` → ``grounding``, ``spatial`` → ``policy`` →
``executor``, ``generation``, ``dialogue``, and ``viz`` for the 3D view. Each package exports
its public names in its ``__init__``; the console script is :func:`assistant.cli.main`.
"""

__version__ = "0.1.0"
