"""The furniture catalogue: model → category, size, shape and front (data in ``data/catalogue.yaml``)."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import yaml

from assistant.errors import DataFileError, UnknownNameError

CATEGORIES = ("small table", "large table", "chair", "couch", "bed")


@dataclass(frozen=True)
class FurnitureModel:
    """One furniture model of the catalogue (sizes in metres, angles in radians)."""

    name: str
    category: str
    length_m: float
    width_m: float
    height_m: float
    shape: str
    front_offset_rad: float | None  # placement yaw → functional front; None: no front

    @property
    def has_front(self) -> bool:
        return self.front_offset_rad is not None

    @property
    def word(self) -> str:
        """The everyday word for the category ("table" for both table categories)."""
        return category_word(self.category)


#: how an object's name is said in a sentence (catalogue ``number``)
NUMBERS = ("one", "plural", "mass")


@dataclass(frozen=True)
class ObjectModel:
    """A small target object (sizes in metres). ``words``: other names people use for it
    ("phone" for ``cell phone``); ``number``: ``plural`` ("the keys are"), ``mass`` ("the mail
    is", no "a"), or ``one``."""

    name: str
    length_m: float
    width_m: float
    height_m: float
    words: tuple[str, ...] = ()
    number: str = "one"


@dataclass(frozen=True)
class Words:
    """The word tables of ``catalogue.yaml``'s ``words`` section (all lower case).

    ``furniture``: furniture word → the categories it can mean (``desk`` → large table);
    ``sizes``: size word → category (``small`` → small table); ``support_names``: category →
    the word a description uses for it; ``synonyms``: word → canonical word; ``phrases``: two
    words → one canonical word; ``descriptors``: word → canonical descriptor.
    """

    furniture: dict[str, tuple[str, ...]]
    sizes: dict[str, str]
    support_names: dict[str, str]
    synonyms: dict[str, str]
    phrases: dict[tuple[str, str], str]
    descriptors: dict[str, str]


@dataclass(frozen=True)
class Catalogue:
    models: dict[str, FurnitureModel]
    objects: dict[str, ObjectModel]
    category_words: dict[str, str]
    words: Words

    def categories_of(self, word: str) -> tuple[str, ...]:
        """The catalogue categories a furniture word can mean (``()`` when it is none)."""
        return self.words.furniture.get(word.strip().lower(), ())

    def suggested_category(self, word: str) -> str | None:
        """The one category a furniture word points to (``desk`` → large table, ``end table`` →
        small table), or None when it can mean several (``table``, ``shelf``) or none."""
        categories = self.categories_of(word)
        return categories[0] if len(categories) == 1 else None

    def model(self, name: str) -> FurnitureModel:
        try:
            return self.models[name]
        except KeyError:
            raise UnknownNameError("furniture model", name, self.models) from None

    def footprints_m2(self, category: str | None) -> tuple[float, ...]:
        """Floor areas (m², length × width) of the models of ``category`` (empty if none)."""
        return tuple(m.length_m * m.width_m for m in self.models.values() if m.category == category)

    def object_words(self) -> dict[str, str]:
        """Every name and other word of the objects (lower case) → the object's name."""
        out: dict[str, str] = {}
        for obj in self.objects.values():
            for word in obj.words:
                out.setdefault(word, obj.name)
        for obj in self.objects.values():  # an object's own name wins over another's word
            out[obj.name] = obj.name
        return out

    def number(self, name: str) -> str:
        """How an object's name is said (:data:`NUMBERS`): the catalogue's ``number`` for a
        known object; for any other thing, ``plural`` when its name ends like a plural
        ("scissors", "papers"), else ``one``."""
        obj = self.objects.get(" ".join(name.lower().split()))
        if obj is not None:
            return obj.number
        last = name.lower().split()[-1] if name.split() else ""
        return "plural" if last.endswith("s") and not last.endswith(("ss", "us", "is")) else "one"

    def object(self, name: str) -> ObjectModel:
        try:
            return self.objects[name]
        except KeyError:
            raise UnknownNameError("object", name, self.objects) from None


def category_word(category: str) -> str:
    return load_catalogue().category_words.get(category, category)


@lru_cache(maxsize=1)
def load_catalogue() -> Catalogue:
    """Load the packaged catalogue once."""
    path = resources.files("assistant.world") / "data" / "catalogue.yaml"
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    where = "catalogue.yaml"
    models: dict[str, FurnitureModel] = {}
    for name, spec in data["models"].items():
        if spec.get("category") not in CATEGORIES:
            raise DataFileError(where, f"models.{name}.category", f"expected one of {CATEGORIES}")
        models[name] = FurnitureModel(
            name=name,
            category=spec["category"],
            length_m=float(spec["length"]),
            width_m=float(spec["width"]),
            height_m=float(spec["height"]),
            shape=str(spec["shape"]),
            front_offset_rad=(float(spec["front_offset"]) if "front_offset" in spec else None),
        )
    objects = {}
    for name, s in data["objects"].items():
        number = str(s.get("number", "one"))
        if number not in NUMBERS:
            raise DataFileError(where, f"objects.{name}.number", f"expected one of {NUMBERS}")
        words = tuple(" ".join(str(w).lower().split()) for w in s.get("words", ()))
        objects[name] = ObjectModel(name, float(s["length"]), float(s["width"]), float(s["height"]),
                                    words, number)
    category_words = {name: spec["word"] for name, spec in data["categories"].items()}
    return Catalogue(models=models, objects=objects, category_words=category_words,
                     words=parse_words(data.get("words"), where))


def parse_words(data, where: str) -> Words:
    """The ``words`` section of a catalogue file (``where`` names it in errors) as :class:`Words`."""
    if not isinstance(data, dict):
        raise DataFileError(where, "words", "expected a mapping of word tables")

    def table(key: str) -> dict:
        value = data.get(key)
        if not isinstance(value, dict):
            raise DataFileError(where, f"words.{key}", "expected a mapping of words")
        return {str(k).lower(): v for k, v in value.items()}

    furniture = {}
    for word, cats in table("furniture").items():
        if not isinstance(cats, list) or not cats or any(c not in CATEGORIES for c in cats):
            raise DataFileError(where, f"words.furniture.{word}", f"expected a list of {CATEGORIES}")
        furniture[word] = tuple(cats)
    phrases = {}
    for phrase, canonical in table("phrases").items():
        parts = tuple(phrase.split())
        if len(parts) != 2:
            raise DataFileError(where, f"words.phrases.{phrase}", "expected two words")
        phrases[parts] = str(canonical).lower()
    sizes = {k: str(v) for k, v in table("sizes").items()}
    for word, category in sizes.items():
        if category not in CATEGORIES:
            raise DataFileError(where, f"words.sizes.{word}", f"expected one of {CATEGORIES}")
    return Words(furniture=furniture, sizes=sizes,
                 support_names={k: str(v) for k, v in table("support_names").items()},
                 synonyms={k: str(v).lower() for k, v in table("synonyms").items()},
                 phrases=phrases,
                 descriptors={k: str(v).lower() for k, v in table("descriptors").items()})
