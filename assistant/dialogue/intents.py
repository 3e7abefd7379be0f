"""Deterministic intent rules: which kind of turn an utterance is, before any parsing.

Control phrases, questions and teaching are recognised by small regular expressions on the
normalised text (lower case, punctuation removed). Everything else is handed to the grounding
parser by the manager: a plan with nodes, a room or an object is a fetch command.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistant.language.shorthand import SECOND_LANGUAGE, SHORTHAND, expand_shorthand  # noqa: F401 (the chat reads them here)
from assistant.dialogue.distances import HOW_FAR
from assistant.dialogue.nearby import NEAR_QUESTION, RELATION

#: how a person may start by addressing the robot ("hey robot, …", "robot, …")
ADDRESS = r"((hey|hi|hello|ok|okay)( there)?( robot)? |robot )?"

#: a thing asked for with no place said; ``thing`` is "my glasses", "the remote"
WANTED = (r"^(?:(?:um|uh|so|ok|okay|well|oh|robot|hey robot|please) )*(?:i need|i want|i would like|id like|"
          r"(?:can|could|may) i (?:have|get)|i (?:really )?need|go (?:and )?(?:get|fetch)|give me|hand me|"
          r"pass me) (?P<thing>(?:my|the|our|his|her|a|an|some) [a-z]+(?: [a-z]+)?)(?: please| now| back| for me)*$")

_PLACE_WORDS = r"(?:on|in|under|by|at|near|next to|beside|behind|inside|in front of|on top of)"
#: a thing's place told, for the robot to remember (groups ``thing`` and ``place``)
TOLD_PLACES = (
    r"^(?:(?:ok|okay|so|and|robot|please) )*(?:please )?(?:can you |could you |will you )?(?:remember|note|make a note|"
    r"keep in mind|dont forget|do not forget)(?: that)?(?: i (?:have |ve )?(?:put|left|placed))? (?P<thing>(?:my|the|our|his|"
    r"her) [a-z]+(?: (?!is\b|are\b|now\b|usually\b|always\b|normally\b)[a-z]+)?) (?:(?:is|are) "
    r"(?:now |usually |always |normally |mostly )?)?(?P<place>" + _PLACE_WORDS + r" [a-z ]+)$",
    # a habit said as a statement: "my keys are always on the coffee table", "my phone lives on the bed"
    r"^(?:(?:ok|okay|so|and|robot|by the way|fyi|just so you know|just to let you know|actually|also) )*"
    r"(?P<thing>(?:my|the|our|his|her) [a-z]+(?: (?!is\b|are\b|usually\b|always\b|normally\b|lives\b|live\b|"
    r"stays\b|stay\b|sits\b|sit\b|belongs\b|belong\b|goes\b|go\b)[a-z]+)?) (?:(?:is|are) (?:usually|always|normally|"
    r"mostly|generally|kept)|(?:usually |always |normally )?(?:lives?|stays?|sits?|belongs?|goes|go|are kept|is kept))"
    r" (?P<place>" + _PLACE_WORDS + r" [a-z ]+?)(?: usually| always| normally| most of the time)?$",
    r"^(?:(?:ok|okay|so|and|robot|by the way|fyi|just so you know|actually|no|sorry) )*(?:i|ive|i have|weve|we have|we) "
    r"(?:just )?(?:put|left|placed|keep|moved) (?P<thing>(?:my|the|our|his|her) [a-z]+(?: (?!(?:next|on|in|under|by|"
    r"at|near|beside|behind|inside|to|onto|into|back|down|away|up|there|here)\b)[a-z]+)?|it|them) "
    r"(?:back |down |away |up )?(?P<place>(?:" + _PLACE_WORDS + r"|to|onto|into) [a-z ]+?)(?: for you| now| again| today)?$",
)
_TELL_LEAD = (r"^(?:(?:ok|okay|so|and|robot|by the way|fyi|just so you know|just to let you know|actually|also|oh|"
              r"well|um|uh|er|right) )*")
_HEDGES = r"(?: i think| i believe| probably| somewhere| i guess| yeah| now| again| as usual| still)*"
TOLD_PLACES += (
    # a place said of one's own thing: "my glasses are by the bed", "my wallets in the office" (the
    # apostrophe gone), "my purse is hanging on the bedroom door", "my keys should be on the desk"
    _TELL_LEAD + r"(?P<thing>(?:my|our|his|her) [a-z]+(?: (?!(?:is|are|was|were|should|must|might|may|will|"
    r"ought)\b)[a-z]+)?) (?:(?:is|are|was|were|should be|must be|might be|may be|will be|ought to be)(?: still| probably|"
    r" somewhere| now| just| right| usually| hanging| sitting| lying| standing| up| down)* )?(?P<place>" + _PLACE_WORDS
    + r" [a-z ]+?)" + _HEDGES + r"$",
    # a hedged place of the thing: "the remote should be somewhere near the couch" (said plainly,
    # "the mug is on the table by the chairs" is the dissertation's fetch description)
    _TELL_LEAD + r"(?P<thing>the [a-z]+(?: (?!(?:is|are|should|must|might|may)\b)[a-z]+)?) (?:should be|must be|"
    r"might be|may be|is probably|are probably|is somewhere|are somewhere|is usually|are usually)(?: somewhere)? "
    r"(?P<place>" + _PLACE_WORDS + r" [a-z ]+?)" + _HEDGES + r"$",
    # two places told at once: "the remotes on the couch and my book is on the bed" (``told_places``)
    _TELL_LEAD + r"(?P<thing>(?:my|the|our|his|her) [a-z]+(?: [a-z]+)?) (?:(?:is|are) )?(?P<place>" + _PLACE_WORDS
    + r" [a-z ]+? and (?:my|the|our|his|her) [a-z]+(?: [a-z]+)? (?:(?:is|are) )?" + _PLACE_WORDS + r" [a-z ]+)$",
)
_TOLD = tuple(re.compile(p) for p in TOLD_PLACES)
#: a thing's place to be forgotten (group ``thing``)
FORGET_THING = (r"^(?:(?:please|ok|okay|and|so|actually|can you|could you|will you) )*(?:forget|delete|drop|clear|erase) "
                r"(?:what (?:i (?:told|said to) you|you know|you remember|youve got|you have) about |about |where |"
                r"the note about |what you know about )?(?P<thing>(?:my|the|our|his|her) [a-z]+(?: (?!is\b|are\b|"
                r"was\b|were\b)[a-z]+)?)(?: (?:is|are|was|were))?(?: please| now| for me| then)*$")
#: a told place put right at once: "no, actually they're in the small room", "no wait, the living
#: room", "sorry, on the dinner table" (group ``place``)
TOLD_CORRECTION = re.compile(
    r"^(?:(?:no|nope|sorry|actually|wait|oh|oops|i mean|my mistake|hang on|correction|no no|not there) )+"
    r"(?:(?:its|theyre|it is|they are|thats|i put (?:it|them)|i left (?:it|them)|i meant) )?(?:(?:actually|really|"
    r"now) )*(?P<place>" + _PLACE_WORDS + r" [a-z ]+|the [a-z ]+)$")
#: one more thing's place after the first: "… and my phone on the bed"
_ANOTHER_TOLD = re.compile(r"(?P<thing>(?:my|the|our|his|her) [a-z]+(?: (?!(?:is|are)\b)[a-z]+)?) (?:(?:is|are) )?"
                           r"(?P<place>" + _PLACE_WORDS + r" [a-z ]+)")


def told_place(norm: str) -> tuple[str, str] | None:
    """(thing, place) of a place told to be remembered ("my keys", "on the coffee table in the
    living room"), or None."""
    for pattern in _TOLD:
        m = pattern.search(norm)
        if m:
            return m.group("thing"), m.group("place")
    return None


def told_places(norm: str) -> list[tuple[str, str]]:
    """Every (thing, place) told in one breath: "I put my keys on the coffee table and my phone on
    the bed" → [("my keys", "on the coffee table"), ("my phone", "on the bed")]; a part after "and"
    that is no thing's place stays with the place before it ("by the table and the chairs")."""
    found = told_place(norm)
    if found is None:
        return []
    thing, place = found
    told = [[thing, ""]]
    for part in re.split(r",? and (?=(?:my|the|our|his|her) [a-z]+)", place):
        m = _ANOTHER_TOLD.fullmatch(part)
        if m is not None and told[-1][1]:
            told.append([m.group("thing"), m.group("place")])
        else:
            told[-1][1] = f"{told[-1][1]} and {part}" if told[-1][1] else part
    return [(_tidy(t), re.sub(_HEDGES + "$", "", _tidy(p))) for t, p in told]


def _tidy(words: str) -> str:
    """Words as meant, without a speaker's hesitations and stutters: "my keys uh" → "my keys",
    "on the the coffee table" → "on the coffee table"."""
    out: list[str] = []
    for w in words.split():
        if w in ("uh", "um", "er", "erm", "hmm", "ah") or (out and out[-1] == w):
            continue
        out.append(w)
    return " ".join(out)


#: a question about what lies on a piece of furniture (groups ``furniture`` and ``room``)
ON_FURNITURE = (r"^(?:(?:and|so|ok|okay|then|um) )*(?:what|whats|what else|what else is|anything|is there anything|"
                r"is anything|are there any things|what things are|what have you seen|what did you see|have you seen anything)"
                r"(?: else)?(?: is| are| lying| left)? (?:on|on top of) (?:the|my|that|this) (?P<furniture>[a-z]+(?: [a-z]+)?)"
                r"(?: (?P<rel>" + RELATION + r") (?:the|my) (?P<landmark>[a-z]+(?: (?!now\b|at\b)[a-z]+)?))?"
                r"(?: (?:in|inside) the (?P<room>[a-z ]+))?(?: now| at the moment)?$")


#: intent name → patterns (searched in the normalised utterance), in priority order
RULES: list[tuple[str, tuple[str, ...]]] = [
    # a person in danger: before anything else, whatever else the words say
    ("emergency", (r"\b(ive|i have|i|has|have|hes|shes|weve) (fallen|fell|had a fall|collapsed)\b",
                   r"\b(cant|can not|cannot) (get up|breathe|move my)\b", r"\bcall (an ambulance|911|999|112|the doctor|"
                   r"a doctor|for help|the police|the fire brigade)\b", r"\b(emergency|ambulance|heart attack|chest pain|"
                   r"bleeding|im hurt|i am hurt|ive hurt myself|i hurt myself|im injured)\b",
                   r"^(help|help me|please help|help me please)( (me|please|robot))*( i .+)$")),
    ("stop", (r"^(?:(?:hang on|hold on|oh|ok|okay|no|please|robot|hey|wait|just|right|whoa|woah|stop) )*(please )?"
              r"(stop|halt|freeze|wait|hold on|hang on|stay)( (it|now|there|right now|please|moving|that|robot|"
              r"a (second|sec|moment|minute)|a sec|for a (second|moment|minute)))*$",
              r"^(stop|halt) (it|now|please)\b")),
    # a told or seen place to be forgotten: "forget what I told you about my keys"
    ("forget", (FORGET_THING,)),
    ("cancel", (r"^(?:(?:actually|ok|okay|oh|no|sorry|well|um|uh|so|ah) )*(please )?(cancel|never ?mind|forget (it|that|"
                r"about it)|abort|no never ?mind)\b",
                r"^(no )?(it doesnt|it does not) matter\b",
                # the thing turned up, or the person lets it go: "no worries", "it's ok, he's found them"
                r"^(?:(?:oh|ok|okay|ah|well|no|actually) )*(no worries|dont worry|do not worry|dont bother|no bother|"
                r"(?:its|it is) (?:ok|okay|alright|fine)(?: now)?(?: (?:i|ive|he|hes|she|shes|we|weve|they|theyve) "
                r"(?:have |has )?found (?:it|them))?|(?:i|ive|he|hes|she|shes|we|weve|they|theyve) (?:have |has )?found (?:it|them)"
                r"(?: now| already)?)(?: thanks| thank you| robot)*$")),
    # a request not to do something: never carried out as the request itself
    ("dont", (r"^(please |no |no no )?(dont|do not|never|better not)( you)? (go|bring|fetch|get|come|drive|move|turn|"
              r"look|search|touch|enter|leave)\b",)),
    ("repeat", (r"\b(repeat that|say that again|say it again|what did you (just )?say|come again)\b",
                r"\b(?:didnt|did not|couldnt|could not) (?:catch|hear|get) (?:that|you|what you said)\b",
                r"^(pardon|sorry what|what|huh|repeat)$",
                r"^(?:(?:please|sorry|can you|could you|robot) )*(repeat|repeat it|say again|what do you mean|what did you "
                r"mean|what does that mean|i dont understand|i didnt understand|i didnt get that|pardon me|"
                r"i (?:cant|can not|cannot|couldnt|didnt) hear (?:you|that|it)|speak up|louder)"
                r"(?: please| again| that| robot)*$")),
    ("help", (r"^(help|help me|\?)$", r"\bwhat can (you|i) (do|say|ask)\b", r"\bwhat (can|could) you help (me )?with\b",
              r"\bhow (can|could) you help( me)?\b", r"\bwhat (are|is) you (for|good at)\b", r"\bhow do(es)? (this|you) work\b",
              r"\bwhat do you (understand|know how to do)\b", r"^(commands|options)$")),
    ("which_home", (r"\b(which|what) (home|house|world|flat|apartment|place) (am i|are we|is this)\b",
                    r"\bwhere am i\b", r"\bwhere are we\b", r"\bwhich rooms\b", r"\bwhat rooms\b",
                    r"\bhow many rooms\b")),
    ("start_over", (r"^(lets )?(start over|start again|begin again|reset|restart|from the (top|beginning))\b",)),
    ("teach", (r"\b(let me|i will|ill|i want to|can i) (show|teach) you\b", r"\bwatch (me|how)\b",
               r"\blearn what\b")),
    # which things the robot knows by sight: "what objects can you recognise?", "can you recognise my slippers?"
    ("what_known", (r"\bwhat (?:things|objects|stuff|items|kind of things|sort of things)(?: else)? (?:can|do|could) you "
                    r"(?:recogni[sz]e|see|find|look for|search for|detect|spot|identify|know)\b",
                    r"\bwhat (?:can|do) you (?:recogni[sz]e|detect|identify)\b",
                    r"\bwhat (?:can|could) you (?:look for|search for)\b",
                    r"\b(?:can|could|do) you (?:recogni[sz]e|detect|identify|tell what) (?P<thing>(?:a|an|my|the|our|his|"
                    r"her|some) [a-z]+(?: [a-z]+)?)(?: look like| looks like)?$",
                    r"\bdo you know what (?P<thing2>(?:a|an|my|the|our|his|her) [a-z]+(?: [a-z]+)?) (?:looks?|look) like\b")),
    # what stands by a piece of furniture: "what's next to the bed?" (dialogue.nearby)
    ("near_furniture", (NEAR_QUESTION.pattern,)),
    # how far a place is from the robot, or which of two is nearer (dialogue.distances)
    ("how_far", HOW_FAR),
    # about the robot itself (before "where": "where are you" asks for the robot, not a thing)
    ("robot_place", (r"^(?:(?:uh|um|er|well|so|and|oh|ok|okay) )*" + ADDRESS + r"(?:so |and |please tell me |tell me )?(where are you|where you are|where are you at|"
                     r"(?:which|what) room (?:are you|you are|you|are you in|you are in|you in)(?: in)?|where have you got to|"
                     r"where did you end up|where are you standing|where exactly are you|where are you exactly|"
                     r"(?:what|which) room is this|what room (?:am i|are we) in)"
                     r"( now| right now| robot| at the moment| exactly)*$",
                     # "which table are you at?": where it stands, by the furniture near it
                     r"^(?:(?:so|and|ok|okay) )*(?:which|what) (?:table|couch|sofa|chair|bed|desk|one|piece of furniture|"
                     r"furniture|thing) (?:are you|you are|you) (?:at|by|near|next to|in front of|beside|facing|looking at)"
                     r"(?: now| right now| exactly)?$")),
    ("why_stopped", (r"\bwhy (?:did|have|has|do) you (?:just )?(?:stop|stopped|stopping|give up|gave up|come back)\b",
                     r"\bwhy (?:are you|you) (?:going|driving|moving|doing that|doing this|going there|turning)\b",
                     r"\bwhy (?:are you|you) (?:not moving|stopped|stopping|standing still)\b", r"^why (?:you )?stop(?:ped)?\b",
                     r"\bwhy (?:didnt|did not|dont|do not|you not) (?:you )?(?:bring|fetch|get|find|finish|go)\b")),
    ("what_see", (r"^" + ADDRESS + r"(?:so |and |now )?what (?:do|can) you see(?: now| there| here| robot| in front of you|"
                  r" around you| from there| from where you are| right now)*$",
                  r"^" + ADDRESS + r"(?:so |and |now )?what(?:s| is| is there)? (?:near|around|next to|in front of|close to|"
                  r"by|beside) you(?: now| right now)?$",
                  r"^" + ADDRESS + r"(?:so |and )?what(?:s| is) (?:in front of you|around you)(?: now)?$",
                  r"^" + ADDRESS + r"(?:so |and )?what(?:s| is)(?: there)? (?:here|in here|around here)(?: now)?$")),
    ("status", (r"^" + ADDRESS + r"(?:are )?you there yet$",
                r"^" + ADDRESS + r"(?:so |and )?(?:where are you (?:going|headed|heading|off to)|how long will (?:it|that|you) "
                r"(?:take|be)|are you nearly (?:there|done))(?: now| robot)?$", r"^" + ADDRESS + r"(what are you doing|what are you up to|are you (done|finished|busy|"
                r"ready|there|still going)|how is it going|hows it going|status|whats happening|what is happening)"
                r"( now| robot| right now)?$",)),
    ("come_here", (r"^(?:(?:no|ok|okay|oh|please|robot|hey|right|actually) )*" + ADDRESS + r"(please )?(come|come here|"
                   r"come back|come to me|come over here|over here|follow me|come and find me|come back here)"
                   r"( please| robot| now| here| to me)*$",
                   r"^(?:(?:ok|okay|now|please|right|and) )*(?:(?:can|could|will|would) you )?(?:go|come|head|drive) back "
                   r"(?:to )?(?:where you (?:started|were|came from|began)|the start|your start|the beginning|"
                   r"your starting (?:point|place)|home|to me)(?: please| now| robot)*$")),
    # go on with the task stopped last ("ok, carry on", "you can continue now")
    ("resume", (r"^(?:(?:ok|okay|alright|right|yes|yeah|sorry|fine|oh|actually|well|no) )*(?:you can |please |ok you can )?(?:carry on|"
                r"continue|keep going|go on|resume|proceed|go ahead and finish|finish (?:it|that|what you were doing)|"
                r"get going again|off you go)(?: please| now| then| with (?:it|that|what you were doing)| robot)*$",)),
    ("wellbeing", (r"^" + ADDRESS + r"(how are you|how are you doing|how are things|hows it going with you|"
                   r"are you (ok|okay|alright|well))( today| robot| this morning| this evening)?$",)),
    ("listening", (r"^" + ADDRESS + r"(are you (listening|awake|on|there|with me)|can you hear me|do you hear me|"
                   r"you there|are you still there|anybody there|hello are you there)( robot| now)?$",)),
    # how the person feels: "I'm feeling a bit lonely today", "sorry dear, I'm a bit confused"
    ("feeling", (r"^(?:(?:oh|well|sorry|um|uh|dear|robot|honestly|you know) )*(?:im|i am|i feel|im feeling|i am feeling|"
                 r"i feel so|feeling)(?: a bit| a little| so| very| quite| really| rather| kind of| bit)* (?:lonely|sad|"
                 r"tired|bored|down|low|unwell|sick|ill|poorly|confused|muddled|scared|frightened|worried|anxious|dizzy|"
                 r"lost|upset|cold|weak)(?: today| now| tonight| this morning| again| dear| robot)*$",)),
    ("smalltalk", (r"^" + ADDRESS + r"(how are you|how are you doing|how do you do|whats your name|what is your "
                   r"name|who are you|are you a robot|what are you)( today| robot)?$",)),
    # things a robot without an arm cannot do to things ("put the mug by the sink", "open the door")
    ("no_arm", (r"^" + ADDRESS + r"(?:please )?(?:(?:can|could|would|will) you (?:please )?)?(?:put|place|drop|set down|"
                r"carry|throw|pour|wash|clean|tidy|cook|open|close|shut|lock|unlock|fold|water|feed|push|lift|pick up)"
                r" (?!(?:me|us|to|up|on)\b)[a-z]",
                # the thing said as "it": "can you pick it up", "could you carry them for me"
                r"^" + ADDRESS + r"(?:please )?(?:(?:can|could|would|will) you (?:please )?)?(?:pick (?:it|them|that|this) up|"
                r"lift (?:it|them)|carry (?:it|them)|hold (?:it|them)|hand (?:it|them) (?:to me|over))\b")),
    ("out_of_scope", (r"\b(whats|what is) the (time|weather|date)\b", r"\bwhat time is it\b",
                      r"\btell (?:me )?the (?:time|date|weather)\b",
                      r"\b(call|phone|ring|text|email|message|video call) (my|the|someone|somebody|a|an|him|her|them)\b",
                      r"\b(make|cook|get|bring|fix|fetch|grab|pour) (me |us )?(a |some )?(cup of |mug of |glass of )?(tea|"
                      r"coffee|dinner|lunch|breakfast|food|a sandwich|something to eat|something to drink|a drink|water|"
                      r"milk|juice|wine|beer)\b",
                      r"\b(tell me a joke|play (some )?music|turn (on|off) the (light|lights|tv|radio|heating))\b",
                      r"\bturn (?:the |my )?(?:light|lights|lamp|tv|telly|television|radio|heating|music|kettle|oven)"
                      r" (?:on|off|up|down)\b",
                      r"\b(battery|batteries|charge level|charged|charging|power level)\b")),
    # doubt about the last answer, or a request to look once more: "are you sure?", "check again"
    ("again", (r"^(?:(?:but|and|so|hmm|really|oh) )*are you (?:sure|certain|positive)(?: (?:about that|its (?:not )?there|"
               r"theyre (?:not )?there|it is (?:not )?there))?$",
               r"^(?:(?:can|could|would|will) you |please )*(?:check|look|search|have a look|take a look|go and look|"
               r"go and check|look for (?:it|them))(?: once)? again(?: please| for me)*$",
               r"^(?:please )?(?:check|look) (?:once )?more$", r"^really$",
               # doubting what was just said: "is that right?", "you sure?", "is it really there?"
               r"^(?:(?:but|and|so|hmm|oh|wait) )*(?:is|was) (?:that|it|this) (?:really )?(?:right|correct|true|so|"
               r"really (?:there|true|so))$", r"^(?:(?:but|and|so|hmm|oh) )*(?:you|u) (?:sure|certain)$",
               r"^(?:(?:but|and|so|hmm|oh) )*(?:are|is) (?:they|it) really there$",
               r"^(?:(?:but|and|so|hmm|oh) )*how (?:are you|can you be|do you know)(?: so)?(?: sure| that)?$")),
    ("seen_list", (r"^(?:(?:and|so|ok|okay|um|well|then|robot) )*(?:what|which things) (?:did|have) you (?:see|seen|find|found|"
                   r"spot|spotted|notice|noticed)(?: so far| today| on your way| there| lately)?"
                   r"(?: (?:in|inside) (?:the|my|our) [a-z]+(?: [a-z]+)?)?(?: so far| today| there| lately)?$",
                   r"\bwhat do you remember\b", r"\bwhat (?:things )?have you seen\b",
                   r"\bwhere (?:have you seen|did you see) (?:things|everything|stuff)\b")),
    # a thing asked for with no place: "I need my glasses", "can I have my keys" (a fetch)
    ("want", (WANTED,)),
    # before "told": "my keys are on the coffee table, right?" is a question
    ("where_check", None),  # WHERE_CHECKS, below: "is my mug in the bedroom?"
    # where a thing is, told to be remembered: "remember that my keys are on the coffee table",
    # "I've put my glasses on the table by the bed"
    ("told", TOLD_PLACES),
    # what lies on a piece of furniture: "what else is on the table?", "is there anything on the bed?"
    ("on_furniture", (ON_FURNITURE,)),
    ("furniture", None),  # FURNITURE_QUESTIONS, below (dialogue.inventory reads them)
    # where a thing should go ("where should I put my keys?"): the person's choice, not a search
    ("put_advice", (r"\bwhere (?:should|shall|do|can|could|would|must|ought) (?:i|we) (?:to )?(?:put|leave|keep|store|"
                    r"place|hang|stick|stash) (?:my|the|our|his|her|this|that|these|those|it|them)\b",
                    r"\bwhere (?:does|do) (?:my|the|our|his|her|this|that|these|those) [a-z]+(?: [a-z]+)? (?:go|belong|live)"
                    r"(?: now)?$")),
    ("where_dynamic", (r"\bhow (do|can|would|should) i (get|go|walk) to\b", r"^how (?:to|i|do you) (?:get|go|walk) to\b", r"\bhow (do|can|would|should) i (get|go) there\b", r"\bhow do i find\b",
                       r"\bwhich way (is|to)\b", r"\bhow (do|can) i reach\b")),
    ("where", (r"\bwhere (is|are|s|was|were|did|do|have)\b", r"\bwheres\b", r"\bwhered\b", r"\bwhereabouts\b",
               # typed in a hurry: "wher is my mug", "whre are my keys"
               r"^(wher|whre|wehre|hwere|whree|were) (is|are|s|did|was) (my|the|our|his|her)\b",
               r"^where (could|might|would|can) (my|the|our|his|her) [a-z ]+ (be|have gone|have got to)$",
               r"^(?:(?:im|i am|were|we are) )?(?:still )?(?:looking|searching) for (?:my|our|the|his|her) [a-z]+"
               r"(?: [a-z]+)?$",
               # where asked inside another sentence: "any idea where my keys are", "tell me where …"
               r"^(.* )?(any idea|no idea|tell me|know|wonder|remember|remind me|show me|see) where\b",
               r"^where (on earth |in the world |the heck |the hell )?(are|is|my|the|our|his|her)\b",
               r"^(.* )?(im|i am|were|we are|been) (looking|searching) (everywhere )?for (my|our|the|his|her) "
               r"[a-z]+( [a-z]+)?( everywhere)?$",
               # a bare search request; with a place ("find my phone in the bedroom") it stays a command
               r"^(please )?((can|could|would|will) you )?(please )?(go (and )?)?(find|locate|search for|look for) "
               r"(my|our|the|his|her) [a-z]+( [a-z]+)?( for me)?( please)?$",
               r"\bhave you seen\b",
               # the thing first, the question after: "the statue? any idea?", "my mug anywhere?"
               r"^(?:(?:and|so|um|uh|oh) )*(?:my|the|our|his|her) [a-z]+(?: [a-z]+)? (?:any idea|any ideas|anywhere|"
               r"seen (?:it|them)|you seen (?:it|them)|know where (?:it is|they are|its|theyre))(?: at all)?$",
               r"\bdid you see\b", r"\bdo you know where\b", r"\bcan you find where\b",
               # a loss told rather than asked: "I can't find my keys", "I've lost my wallet"
               r"\b(cant|can not|cannot|couldnt|could not) find (my|our|the|his|her)\b",
               r"\b(ive|i have|i|weve|we have|we|she|he|has) (lost|misplaced|mislaid)\b",
               r"\b(lost|misplaced|mislaid|cant find|cannot find) (my|his|her|our|their|the) [a-z]+",
               r"\bhelp me (find|look for)\b", r"^(you|anyone|anybody|has anyone|has anybody) seen\b",
               # about the thing just talked of: "which room is it in?", "where exactly?", "which table exactly?"
               r"^(?:(?:and|so|ok|okay|but) )*which (room|table|one|place|chair|bit of the room) (is|are) (it|they|that|"
               r"those) (in|on|at)$",
               r"^(?:(?:and|so|ok|okay|but|sorry) )*(?:which|what) (?:room|table|desk|place|bit of the room)(?: (?:is|was) "
               r"(?:that|it)| are they| were they| exactly)?$",
               r"^(?:(?:and|so|ok|okay|but) )*(which|what) (room|table|place) (is|are) (my|the|our|his|her) [a-z]+"
               r"(?: [a-z]+)? (in|on|at)$",
               r"^(?:and|what about|how about|and what about) (my|the|our|his|her) [a-z]+(?: [a-z]+)?$",
               r"^(?:and|what about|how about|and what about) (?:in|inside|on) (?:the|my|our) [a-z]+(?: [a-z]+)?$",
               r"^(?:(?:and|so|well|ok) )*did you (?:find|see|spot) (?:it|them|my|the|our|his|her)\b",
               r"\bwhere exactly (?:is|are) (?:it|they)\b", r"\bdescribe (?:where|it|them)\b",
               r"\b(?:tell|show) me how to (?:find|get to) (?:it|them)\b",
               r"^(?:(?:and|so|ok|okay|but) )*which (table|room|one)$", r"^(?:(?:and|so|ok|okay|but) )*(where|which (room|table|one|place)) "
               r"(exactly|precisely|then)$")),
    ("bye", (r"^(ok |okay |thanks |thank you |no problem |no problem thanks |cheers )*(bye|goodbye|good bye|bye bye|see you|see ya|quit|exit|good night|"
             r"thats all|that is all|im done|i am done)( now| then| for now| robot| brian| later)*$",)),
    ("yes", (r"^(yes|yeah|yep|yup|sure|ok|okay|please do|do it|go ahead|please|go|y|of course|correct|right|"
             r"yes please|go and check|check|sure thing)$",
             # said together: "sure, go ahead", "yes please do", "ok go and get it"
             r"^(yes|yeah|yep|yup|sure|ok|okay|alright|please|of course)( (yes|please|sure|go ahead|do it|please do|"
             r"go|go for it|go and check|go and get (it|them)|get (it|them)|why not|check|check it|check please|"
             r"look|have a look|take a look|go and look|go check|go look|go and see|thats it|that is it|thats the one|"
             r"that one|thats right|that is right|take me to (?:it|them)|take me there|bring me there|show me))+$",
             # "cool go there", "you go there now please", "ok go on then"
             r"^(?:(?:ok|okay|cool|great|good|yes|yeah|sure|alright|fine|then|please|you|now|so|can you|could you|"
             r"will you|would you) )*(?:go there|go "
             r"over there|go on then|go on|go for it|off you go|take me there|show me|bring me there|"
             r"show me where|lead the way|lead me there)(?: now| please| then| robot)*$")),
    ("no", (r"^(no|nope|nah|no thanks|no thank you|dont|do not|n|not now|leave it)$",
            r"^(no|nope|nah|not|not now|not right now|not yet|maybe later|later|no need|its fine|its ok|"
            r"(no )?(just )?leave (it|them)( there| be| alone)?)( thanks| thank you| robot| then| for now)*$")),
    ("greet", (r"^(hi|hello|hey|hiya|good (morning|afternoon|evening)|howdy)( there| robot)?$",
               # with a name: "hello there, my name is Mary"
               r"^(?:hi|hello|hey|hiya|good (?:morning|afternoon|evening))(?: there| robot)? (?:my name is|my names|"
               r"im|i am|this is|its) [a-z]+$")),
    ("praise", (r"^(?:youre|you are) (?:a star|a gem|a treasure|the best|great|wonderful|brilliant|so clever|a "
                r"good robot|very clever|amazing)(?: robot| dear| thanks| thank you)*$",
                r"^(that is |thats |very |youre a |you are a |what a )?(good robot|good boy|good girl|nice work|nice one|"
                r"great job|well done|good job|clever (robot|thing|little thing|boy|girl)|great|awesome|perfect|"
                r"brilliant|excellent|wonderful|lovely|clever)( robot| thanks| thank you)*$",
                r"^(ok |okay |oh )?(good|great|nice|cool|super|lovely|brilliant|excellent|good good)( robot| thanks| thank you)*$",
                r"^(youre|you are) (so |very |a )?(clever|smart|good|great|helpful|brilliant)\b")),
    ("thanks", (r"\b(thank you|thanks|cheers|great job|well done|good job)\b", r"^ta( very much| robot| love| dear)?$")),
    # an acknowledgement with nothing asked ("ok, that's fine", "alright then", "cool cool")
    ("ack", (r"^(?:(?:ok|okay|oh|ah|right|alright|all right|cool|fine|good|great) )*(?:thats|that is|its|it is) "
             r"(?:fine|ok|okay|alright|good|great|grand)(?: then| thanks| thank you)*$",
             r"^(?:ok|okay|alright|all right|right|cool|fine|got it|i see|understood|noted)(?: (?:ok|okay|cool|then|"
             r"right|fine|got it))+$")),
    ("rude", (r"\b(stupid|idiot|dumb|useless|shut up|hate you|moron|rubbish robot|piece of junk)\b",)),
]

#: questions about the home's furniture, by kind (dialogue.inventory): what is in a room; is there
#: a piece; how many
_IN_ROOM = (r"(?: (?:in|inside) (?:the|my|our|this) [a-z ]+| here| in here| around here| at home|"
            r" in (?:the|this|my|our) (?:house|home|apartment|flat|place))?")
_LEAD = r"^(?:(?:and|so|also|um|uh|er|well|then|oh|ok|okay|now|tell me) )*" + ADDRESS
FURNITURE_QUESTIONS = (
    _LEAD + r"(?:what|whats|which) (?:furniture|things|stuff|pieces of furniture)? ?(?:is |are )?"
    r"(?:there )?(?:in|inside) (?:the|my|our|this) [a-z ]+$",
    _LEAD + r"(?:is|are) there (?P<what>[a-z ]+?)" + _IN_ROOM + r"$",
    _LEAD + r"how many (?P<what>[a-z ]+?) (?:are there|are|is there|do we have|do i have|do you know of|"
    r"can you see|do you see|have we got|have i got)" + _IN_ROOM + r"$",
)
#: a yes-or-no question whether a thing is at a place: "is my mug in the bedroom?", "did I leave my
#: keys on the table?", "could my glasses be in the living room?", "is it still on the couch?"
_THING = r"(?P<thing>(?:my|the|our|his|her) [a-z]+(?: (?!still\b|maybe\b|perhaps\b|by\b|now\b)[a-z]+)?|it|they|them)"
_PLACE = (r"(?P<place>(?:in|on|under|by|at|near|next to|beside|behind|inside|in front of) [a-z]+(?: [a-z]+)*?"
          r"|upstairs|downstairs)(?: still| now| then| by any chance| perhaps| maybe)?$")
_TAG = r"(?: (?:yes|right|no|isnt it|arent they|correct|yeah|true|is it|are they))$"
WHERE_CHECKS = (
    _LEAD + r"(?:is|are) " + _THING + r" (?:still |maybe |perhaps |by any chance )?" + _PLACE,
    # a statement with a question tag: "my monitor is in the studio, right?", "monitor is in studio, yes?"
    _LEAD + r"(?P<thing>(?:(?:my|the|our|his|her) )?[a-z]+(?: [a-z]+)?) (?:is|are) (?:still )?"
    + _PLACE[:-1] + _TAG,
    _LEAD + r"(?:did|have|do) (?:i|we|you|he|she) (?:leave|left|put|seen|see|keep|last see) " + _THING + r" " + _PLACE,
    _LEAD + r"(?:could|might|would|can) " + _THING + r" be " + _PLACE,
)
_WHERE_CHECKS = tuple(re.compile(p) for p in WHERE_CHECKS)


def where_check_parts(norm: str) -> tuple[str, str] | None:
    """(thing, place) of a normalised yes-or-no place question ("my mug", "in the bedroom"), or None."""
    for pattern in _WHERE_CHECKS:
        m = pattern.search(norm)
        if m:
            return m.group("thing"), m.group("place")
    return None


RULES = [(name, (FURNITURE_QUESTIONS if name == "furniture" else WHERE_CHECKS) if patterns is None else patterns)
         for name, patterns in RULES]

_COMPILED = [(name, tuple(re.compile(p) for p in patterns)) for name, patterns in RULES]


#: clauses of courtesy that ask nothing ("could you, if it's not too much trouble, look …")
COURTESIES = re.compile(r"[,;]?\s*\b(?:if (?:it is|its|it's|that is|thats|that's) not too much (?:trouble|bother)(?: for you)?|"
                        r"if you (?:dont|don't|do not) mind|when you (?:have|get) (?:a|the) (?:moment|minute|second|chance)|"
                        r"if (?:you can|you could|you would|you please|possible|you have time)|"
                        r"(?:and )?(?:i|we) (?:would|'d|d) (?:be (?:very |so )?grateful|appreciate it))\b\s*[,;]?",
                        re.IGNORECASE)
#: a first sentence of thanks or agreement before a request ("Thank you. Could you please …")
#: a first clause that drops what went before, then a new request ("never mind, where's my knitting")
LEADING_NEVER_MIND = re.compile(r"^\s*(?P<lead>(?:oh |ok |okay |no )?(?:never ?mind|forget (?:it|that)|cancel that|"
                                r"scratch that|leave it|doesnt matter|it doesnt matter)(?: then| dear| robot)?)\s*[.!,;-]*\s+"
                                r"(?P<rest>\S.*)$", re.IGNORECASE)
LEADING_THANKS = re.compile(r"^\s*(?P<lead>(?:ok(?:ay)?,? )?(?:thank you(?: (?:so|very) much)?|thanks(?: a lot| so much)?|cheers|"
                            r"ta|lovely|great|perfect|good|ok|okay|alright)(?: robot| dear)?)\s*[.!,;]+\s+(?P<rest>\S.*)$",
                            re.IGNORECASE)


def drop_courtesies(text: str) -> str:
    """``text`` without the clauses of :data:`COURTESIES` ("And then, if it is not too much
    trouble, could you look at the table" → "And then could you look at the table")."""
    out = COURTESIES.sub(" ", text or "")
    return re.sub(r"\s+([,.?!])", r"\1", re.sub(r"\s{2,}", " ", out)).strip() or (text or "")


def normalise(text: str) -> str:
    """Lower case, apostrophes dropped ("where's" → "wheres"), other punctuation to spaces."""
    t = (text or "").lower().replace("’", "'").replace("'", "")
    t = re.sub(r"[^a-z0-9? ]+", " ", t)
    t = re.sub(r"\s*\?\s*", " ", t) if t.strip() != "?" else "?"
    return " ".join(t.split())


@dataclass(frozen=True)
class Intent:
    name: str  # a RULES name, or "command" (for the parser) or "empty"
    text: str  # the normalised utterance


#: said before a sentence without adding to it ("uh what are you doing", "well where are you")
FILLERS = re.compile(r"^(?:(?:uh|um|er|erm|hmm|hm|ah|oh|well|so|like|right|now|okay so|ok so|and|but|say|listen|"
                     r"excuse me|sorry|hey|hi|hello|robot)\s+)+")
#: said after it to the listener ("where are you now, dear?"): always dropped
VOCATIVES = re.compile(r"(?:\s+(?:dear|dearie|love|darling|sweetie|honey|mate|buddy|pal|my friend|my dear))+$")
#: said after it, dropped when the whole sentence matched no rule
CLOSINGS = re.compile(r"(?:\s+(?:robot|then|please|for me|thanks|thank you))+$")


def classify(text: str) -> Intent:
    """The first rule that matches; ``command`` when none does (the parser decides). When none
    does, the utterance without its leading fillers and closing vocatives (:data:`FILLERS`,
    :data:`VOCATIVES`) is tried too: "uh what are you doing", "where are you now, dear"."""
    norm = normalise(text)
    norm = VOCATIVES.sub("", norm) or norm
    if not norm:
        return Intent("empty", norm)
    for name, patterns in _COMPILED:
        if any(p.search(norm) for p in patterns):
            return Intent(name, norm)
    bare = CLOSINGS.sub("", FILLERS.sub("", norm))
    if bare and bare != norm:
        for name, patterns in _COMPILED:
            if any(p.search(bare) for p in patterns):
                return Intent(name, bare)
    return Intent("command", norm)


ORDINALS = {"first": 0, "1st": 0, "one": 0, "1": 0, "second": 1, "2nd": 1, "two": 1, "2": 1,
            "third": 2, "3rd": 2, "three": 2, "3": 2, "fourth": 3, "4th": 3, "four": 3, "4": 3,
            "last": -1, "final": -1}


def ordinal_choice(norm: str) -> int | None:
    """Index picked by "the second", "the first one", "number 2", "the last"; None if none."""
    words = norm.split()
    if len(words) > 5:
        return None
    for w in words:
        if w in ORDINALS and w not in ("one",):
            return ORDINALS[w]
    if words in (["one"], ["the", "one"]):
        return None
    return None


TEACH_PHRASE = re.compile(r"""['"‘“]([^'"’”]+)['"’”]""")


def teach_phrase(text: str) -> str | None:
    """The phrase to be taught: quoted, or what follows "what"/"how to go" up to "means"."""
    m = TEACH_PHRASE.search(text or "")
    if m:
        return m.group(1).strip()
    norm = normalise(text)
    m = re.search(r"\b(?:what|where) (.+?) (?:means|is)\b", norm) or re.search(r"\bshow you (?:how to go )?(.+)$", norm)
    return m.group(1).strip() if m else None


#: intents that are never an answer to the robot's question: they drop it and are handled as
#: themselves ("bye" while it asks "which table?")
NEW_REQUESTS = frozenset({"where", "where_dynamic", "teach", "greet", "help", "which_home", "bye", "thanks",
                          "status", "come_here", "smalltalk", "out_of_scope", "furniture", "rude",
                          "seen_list", "no_arm", "want", "dont", "put_advice",
                          "where_check", "resume", "emergency", "wellbeing", "listening", "feeling",
                          "praise", "told", "forget", "what_known", "on_furniture", "near_furniture", "how_far", "robot_place", "why_stopped", "what_see", "ack", "again"})

#: words of a request that are politeness, not content (never "unknown words")
POLITE_WORDS = {"please", "robot", "could", "would", "can", "you", "kindly", "thanks", "thank", "hey", "now",
           "just", "quickly", "for", "bring", "get", "fetch", "grab", "find", "look", "fetching", "check",
           "search", "explore", "visit", "inspect", "peek", "see", "show", "lead", "guide", "way"}

#: phrases that name no place ("teach me something")
VAGUE_PHRASES = {"something", "this", "that", "it", "a place", "how", "where", "a thing", "what i mean"}
