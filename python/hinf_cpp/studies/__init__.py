"""Studies: many runs of one scenario with some of its keys varied (docs/studies.md).

:func:`load_study` reads a study file, :func:`run_study` runs it (locally or on Dask) into a
pandas DataFrame, :func:`replay` runs one row again. :mod:`hinf_cpp.studies.report` summarizes
and plots a table (it imports matplotlib).
"""

from hinf_cpp.studies.study import (STATUSES, ClusterError, GridAxis, RandomAxis, Study, load_study, local_cores,
                                    replay, replay_command, replay_commands, run_study, study_from_dict,
                                    study_table_schema)

__all__ = ["STATUSES", "ClusterError", "GridAxis", "RandomAxis", "Study", "load_study", "local_cores", "replay",
           "replay_command", "replay_commands", "run_study", "study_from_dict", "study_table_schema"]
