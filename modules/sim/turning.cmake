# The turning stock: revolved profiles in the XZ half-plane, cut by a grooving/turning insert,
# and the checks on a traced lathe program (issue 14).
set(SIM_PART_SOURCES TurningStock.cpp TurningProfile.cpp TurningCheck.cpp)
