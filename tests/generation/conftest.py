"""Fixtures of the generation tests: the corpus-trained model (once per session) and a tiny
hand-written stand-in corpus for the learning tests."""

from __future__ import annotations

import pytest

TINY_XML = """<ALL>
<S id="t1" world="w" object="mug" room="living room" kind="static">
  <OBTP><DT>the</DT><NN>mug</NN><VBZ>is</VBZ>
    <FURTP><ON>on</ON><DT>the</DT><FUR>table</FUR>
      <FURRP><IN>in</IN><DIR>front</DIR><IN>of</IN><DT>the</DT><FUR>couch</FUR></FURRP>
    </FURTP>
    <ORMTP><IN>in</IN><DT>the</DT><NN>living</NN><RM>room</RM></ORMTP>
  </OBTP>
</S>
<S id="t2" world="w" object="fork" room="bedroom" kind="static">
  <OBTP><DT>the</DT><NN>fork</NN><VBZ>is</VBZ>
    <ORMTP><IN>in</IN><DT>the</DT><RM>bedroom</RM></ORMTP>
    <FURTP><ON>on</ON><DT>the</DT><FUR>table</FUR>
      <IRMRP><IN>against</IN><DT>the</DT><DIR>left</DIR><STR>wall</STR></IRMRP>
    </FURTP>
  </OBTP>
</S>
<S id="t3" world="w" object="fork" room="bedroom" kind="dynamic">
  <ORMTP><VB>go</VB><IN>into</IN><DT>the</DT><RM>bedroom</RM></ORMTP>
  <IRMRP><VB>turn</VB><DIR>right</DIR></IRMRP>
  <OBTP><PRP>you</PRP><MD>'ll</MD><VB>find</VB><DT>the</DT><NN>fork</NN></OBTP>
</S>
</ALL>
"""

TINY_CSV = """CMD#,Chunk Name,Chunk Content,target room,target object,reference,direction,target
1,OBTP,DT the NN mug VBZ is,N/A,mug,N/A,N/A,N/A
1,FURTP,ON on DT the FUR table,N/A,N/A,N/A,N/A,table
1,FURRP,IN in DIR front IN of DT the FUR couch,N/A,N/A,couch,front,N/A
1,ORMTP,IN in DT the NN living RM room,living room,N/A,N/A,N/A,N/A
2,OBTP,DT the NN fork VBZ is,N/A,fork,N/A,N/A,N/A
2,ORMTP,IN in DT the RM bedroom,bedroom,N/A,N/A,N/A,N/A
2,FURTP,ON on DT the FUR table,N/A,N/A,N/A,N/A,table
2,IRMRP,IN against DT the DIR left STR wall,N/A,N/A,wall,left,N/A
3,ORMTP,VB go IN into DT the RM bedroom,bedroom,N/A,N/A,N/A,N/A
3,IRMRP,VB turn DIR right,N/A,N/A,move,right,N/A
3,OBTP,PRP you MD 'll VB find DT the NN fork,N/A,fork,N/A,N/A,N/A
"""


@pytest.fixture()
def tiny_corpus(tmp_path):
    xml = tmp_path / "tiny.xml"
    csv = tmp_path / "tiny_chunk_groundings.csv"
    xml.write_text(TINY_XML, encoding="utf-8")
    csv.write_text(TINY_CSV, encoding="utf-8")
    return [xml, csv]


@pytest.fixture(scope="session")
def generation_model():
    from assistant.generation import load_generation_model

    return load_generation_model()


@pytest.fixture(scope="session")
def describer(generation_model):
    from assistant.generation import Describer

    return Describer(generation_model)
