"""The four commands: ``glyphbench`` (``main``: list, show, play, random, bench, replay, plot),
``glyphbench-train`` (``train``), ``glyphbench-eval`` (``eval``) and ``glyphbench-sweep``
(``sweep``). Each parses its arguments, calls the library and turns its errors into one line."""
