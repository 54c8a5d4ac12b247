"""Dataset exports: generated objects in the layouts learning code reads (docs/export.md).

>>> import infmob_usd
>>> infmob_usd.export("partnet-mobility", "objects", "pm", split="train=0.8,val=0.1,test=0.1")

Formats: ``partnet-mobility`` (:mod:`.partnet`, :mod:`.layout`), ``gapartnet`` (:mod:`.gapartnet`, on top
of it), ``cage`` (:mod:`.cage`). :mod:`.run` streams a folder of objects through a pool and resumes;
:mod:`.card` writes splits and ``DATASET.md``; :mod:`.source` reads source folders as hostile input.
"""

from .run import FIRST_ID, FORMATS, export
from .source import ExportError

__all__ = ["FIRST_ID", "FORMATS", "ExportError", "export"]
