# freecadcmd starting and importing what freecad_sim_gcode.py imports, with no simulation: the
# fixed part of the FreeCAD side's time in sim_vs_freecad.sh's breakdown.
import FreeCAD  # noqa: F401
import Mesh  # noqa: F401
import Part  # noqa: F401
import Path  # noqa: F401
import PathSimulator  # noqa: F401
