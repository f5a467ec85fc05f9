"""Measured data of a tap test: modal parameters from a measured FRF, the FRF from impact records.

Pure analysis on measured data (no deck, no files written): the runs and the writers of ``output/`` build on
it.  The identification wraps sdypy-EMA (LSCF poles, LSFD residues) in :mod:`.ema`, the impact processing
wraps pyFRF (H1, coherence, double-hit and overload checks) in :mod:`.frf_estimation`; a version change of
either library touches that one module.

* :func:`identify_modes` -> :class:`ModalIdentification` (the stable-pole rule in :mod:`.stabilisation`);
* :func:`read_impact_records` (CSV, UFF 58 time records) and :func:`frf_from_impacts` -> :class:`ImpactFrf`.
"""

from spindlesim.lazy import lazy_exports

_EXPORTS = {
    "identify_modes": "identification",
    "IdentificationError": "errors",
    "MeasurementInputError": "errors",
    "StabilityCriteria": "stabilisation",
    "ModalIdentification": "results",
    "DirectionIdentification": "results",
    "IdentifiedMode": "results",
    "DiscardedMode": "results",
    "ImpactRecord": "results",
    "ImpactFrf": "results",
    "ImpactVerdict": "results",
    "frf_from_impacts": "impact",
    "read_impact_records": "records",
    "RecordFileError": "records",
}

__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = list(_EXPORTS)
