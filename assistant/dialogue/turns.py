"""One exchange of a conversation (:class:`Turn`), the help text, and joining words."""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["HELP_TEXT", "NUMBER_WORDS", "SOCIAL_REPLIES", "Turn", "join_words"]

NUMBER_WORDS = {2: "two", 3: "three", 4: "four", 5: "five", 6: "six"}
HELP_TEXT = ("You can send me to your things (\"bring me the mug from the table in front of the couch "
             "in the living room\" — I go and find it; I have no arm to carry it), ask where something is (\"where is my mug?\", \"have you seen my "
             "laptop?\"), how to get to it (\"how do I get to my fork?\"), how far it is (\"how far is the bedroom?\"), "
             "tell me where a thing is (\"my glasses are by the bed\"), or teach me a place "
             "(\"let me show you what 'in front of the couch' means\"). Say \"stop\" to stop me, "
             "\"repeat that\", \"which home am I in\", \"start over\" or \"bye\".")
#: intent → the reply to it (what people say to a robot besides requests)
SOCIAL_REPLIES = {
    "greet": "Hello! What can I do for you?",
    "ack": "OK.",
    "thanks": "You're welcome.",
    "praise": "Thank you — I'm glad I could help.",
    "wellbeing": "I'm fine, thank you — ready to help. What can I do for you?",
    "feeling": "I'm sorry to hear that. I'm here: I can look for your things, tell you where they are, or go "
               "somewhere for you — for example \"where are my glasses?\". If you feel unwell, please call someone "
               "close to you or your care line.",
    "listening": "Yes, I'm here and listening. What can I do for you?",
    "emergency": "I can't call anyone or help you up myself. Please use your alarm button or your phone to call "
                 "for help now — 999, 911 or 112, or someone close by. I'm staying here.",
    "rude": "I'm sorry I'm not being more helpful. Tell me what you need, for example \"bring me the mug "
            "from the bedroom\".",
    "smalltalk": "I'm the home robot: I find things, tell you where they are and go to them. What can I do "
                 "for you?",
    "out_of_scope": "I can't help with that: I find things in this home, tell you where they are and go to "
                    "them. Say \"help\" for examples.",
    "no_arm": "I can't pick things up, carry them or open things: I have no arm. I can find your things, tell "
              "you where they are and take you to them — for example \"where is my mug?\" or \"go to the couch\".",
    "put_advice": "That's up to you — wherever you'll think of looking. Once it's there, tell me, for example "
                  "\"the mug is on the table in the bedroom\", and I'll go and have a look, so I know where it is.",
    "come_here": "I can't see where you are. Tell me where to go, for example \"go to the living room\".",
}


@dataclass
class Turn:
    """One exchange: what was said, the intent, the robot's reply, what it did and how it ended.

    ``action``: ``answer``, ``describe``, ``fetch``, ``search``, ``clarify``, ``teach``, ``stop``,
    ``leave`` (the conversation ends: "bye"), ``none``; ``outcome``: ``answered``, ``asked``,
    ``started``, ``success``, ``failed``, ``stopped``, ``cancelled``, ``not_understood``, ``busy``;
    ``seconds``: time to the reply (wall clock).
    """

    text: str
    intent: str
    reply: str
    action: str = "none"
    outcome: str = "answered"
    data: dict = field(default_factory=dict)
    seconds: float = 0.0
    final: bool = True  # False for a started fetch: a final Turn follows from the worker

    def to_dict(self) -> dict:
        return {"text": self.text, "intent": self.intent, "reply": self.reply, "action": self.action,
                "outcome": self.outcome, "data": self.data, "seconds": round(self.seconds, 4)}


def join_words(words: list[str], last: str = "and") -> str:
    """"a", "a and b", "a, b and c" (``last`` instead of "and")."""
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + f" {last} " + words[-1]
