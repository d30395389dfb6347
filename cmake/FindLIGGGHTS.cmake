# SPDX-License-Identifier: GPL-2.0-or-later
# Finds Debian's LIGGGHTS 3.8 development files (package libliggghts-dev):
# headers under /usr/include/liggghts and libliggghts.so. Defines LIGGGHTS::LIGGGHTS.
find_path(LIGGGHTS_INCLUDE_DIR NAMES lammps.h fix.h modify.h
  PATH_SUFFIXES liggghts)
find_library(LIGGGHTS_LIBRARY NAMES liggghts)
if(NOT LIGGGHTS_INCLUDE_DIR OR NOT LIGGGHTS_LIBRARY)
  message(FATAL_ERROR
    "LIGGGHTS 3.8 development files not found (need /usr/include/liggghts/lammps.h and "
    "libliggghts.so). Install the Debian package: apt-get install libliggghts-dev liggghts")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LIGGGHTS REQUIRED_VARS LIGGGHTS_LIBRARY LIGGGHTS_INCLUDE_DIR)
if(NOT TARGET LIGGGHTS::LIGGGHTS)
  add_library(LIGGGHTS::LIGGGHTS UNKNOWN IMPORTED)
  # Debian's library is built without superquadric/non-spherical particles and with the
  # default integer sizes (LAMMPS_SMALLBIG): compile our styles with the same layout.
  set_target_properties(LIGGGHTS::LIGGGHTS PROPERTIES
    IMPORTED_LOCATION ${LIGGGHTS_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${LIGGGHTS_INCLUDE_DIR}
    INTERFACE_COMPILE_DEFINITIONS "LAMMPS_SMALLBIG")
endif()
