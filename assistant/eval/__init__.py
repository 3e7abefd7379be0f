"""The dissertation's experiments, reproduced on this product (``assistant eval NAME``).

One module per evaluation, named as on the command line: :mod:`~assistant.eval.tagging`,
:mod:`~assistant.eval.grounding`, :mod:`~assistant.eval.perception`,
:mod:`~assistant.eval.policy`, :mod:`~assistant.eval.fetch`, :mod:`~assistant.eval.generation`
and :mod:`~assistant.eval.dialogue`. This package sits above the application and dialogue
layers: it calls their public APIs and is called only by the command line. Nothing is imported
here, so importing one evaluation does not pay for the others.
"""
