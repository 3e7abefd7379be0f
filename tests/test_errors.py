"""One NotFittedError for every learned model, an AssistantError the CLI prints as one line."""

import pytest

from assistant.errors import AssistantError, NotFittedError


def test_every_learned_model_raises_the_one_not_fitted_error():
    from assistant.generation.model import GenerationModelNotFittedError
    from assistant.grounding.base import GrounderNotFittedError
    from assistant.language.chunker import NestedChunker
    from assistant.language.postag import SemanticPosTagger

    assert GenerationModelNotFittedError is NotFittedError is GrounderNotFittedError
    assert issubclass(NotFittedError, AssistantError)
    with pytest.raises(NotFittedError):
        SemanticPosTagger().tag(["go", "left"])
    with pytest.raises(NotFittedError):
        NestedChunker().label(["go"], ["VB"])
