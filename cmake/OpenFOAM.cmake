# OpenFOAM v1912 (Debian's `openfoam` package + the headers of the same version).
#
#   include(cmake/OpenFOAM.cmake)
#
# Inputs (cache variables):
#   FSI_OPENFOAM_SRC     the src/ folder of the header cache made by scripts/ensure_openfoam.sh
#                        (default: <source>/build-deps/openfoam-1912/src)
#   FSI_OPENFOAM_LIBDIR  where Debian installs the OpenFOAM libraries (default: /usr/lib)
#   FSI_REQUIRE_OPENFOAM stop with an error, instead of a warning, when OpenFOAM is missing
# Outputs:
#   FSI_HAVE_OPENFOAM    TRUE when the targets below exist
#   FSI_OPENFOAM_ENV     run-time environment for OpenFOAM programs ("WM_PROJECT_DIR=..."), a
#                        list usable in set_tests_properties(... ENVIRONMENT ...)
#   FSI_OPENFOAM_BIN     folder of Debian's OpenFOAM programs (blockMesh, pimpleFoam...)
#   targets (imported; link them, they carry includes, definitions, flags and libraries):
#     OpenFOAM::OpenFOAM       core (+ OSspecific/POSIX headers)
#     OpenFOAM::fileFormats, OpenFOAM::surfMesh, OpenFOAM::meshTools
#     OpenFOAM::finiteVolume   fvCFD.H and friends (brings meshTools)
#     OpenFOAM::transport      incompressible transport models (singlePhaseTransportModel)
#     OpenFOAM::turbulence     incompressible turbulence models + transport models (RAS, LES,
#                              DES: SpalartAllmarasDES/DDES/IDDES, kOmegaSSTDES...)
#     OpenFOAM::sampling, OpenFOAM::fvOptions
#     OpenFOAM::dynamicMesh, OpenFOAM::dynamicFvMesh (mesh motion; brings topoChangerFvMesh)
#     OpenFOAM::solverLibs     everything Debian's pimpleFoam links (for a pimpleFoam-like solver)
#
# The compile flags are those wmake used for the Debian build (wmake/rules/General, linux64Gcc):
# -DOPENFOAM=1912 -DWM_DP -DWM_LABEL_SIZE=32 -DNoRepository -ftemplate-depth-100. The libraries
# have no SONAME and register their models through static constructors, so they are linked by
# name (-lfoo) and without --as-needed, as wmake does.

set(FSI_OPENFOAM_SRC "${CMAKE_SOURCE_DIR}/build-deps/openfoam-1912/src" CACHE PATH
    "src/ folder of the OpenFOAM v1912 header cache (made by scripts/ensure_openfoam.sh)")
set(FSI_OPENFOAM_LIBDIR "/usr/lib" CACHE PATH "folder of Debian's OpenFOAM libraries")
option(FSI_REQUIRE_OPENFOAM "Fail the configuration when OpenFOAM is not available" OFF)

set(FSI_HAVE_OPENFOAM FALSE)
set(FSI_OPENFOAM_ENV "WM_PROJECT_DIR=/usr/share/openfoam" "FOAM_ETC=/usr/share/openfoam/etc")
set(FSI_OPENFOAM_BIN "/usr/bin")

function(_fsi_openfoam_missing what)
  string(CONCAT msg "OpenFOAM v1912: ${what}.\n  Run: scripts/ensure_openfoam.sh  (installs Debian's openfoam "
          "package and caches the headers), then configure again with "
          "-DFSI_OPENFOAM_SRC=<cache>/src if the cache is not the default "
          "build-deps/openfoam-1912.\n  The fluid solver and its tests are left out.")
  if(FSI_REQUIRE_OPENFOAM)
    message(FATAL_ERROR "${msg}")
  else()
    message(WARNING "${msg}")
  endif()
endfunction()

if(TARGET OpenFOAM::OpenFOAM)
  set(FSI_HAVE_OPENFOAM TRUE)
  return()
endif()

if(NOT EXISTS "${FSI_OPENFOAM_SRC}/OpenFOAM/lnInclude/argList.H" OR
   NOT EXISTS "${FSI_OPENFOAM_SRC}/finiteVolume/lnInclude/fvCFD.H")
  _fsi_openfoam_missing("no headers in FSI_OPENFOAM_SRC=${FSI_OPENFOAM_SRC}")
  return()
endif()
if(NOT EXISTS "${FSI_OPENFOAM_LIBDIR}/libOpenFOAM.so")
  _fsi_openfoam_missing("no libOpenFOAM.so in FSI_OPENFOAM_LIBDIR=${FSI_OPENFOAM_LIBDIR}")
  return()
endif()

# _fsi_openfoam_lib(NAME LIBRARY library-file-stem INCLUDES dirs... DEPS targets...)
function(_fsi_openfoam_lib name)
  cmake_parse_arguments(A "" "LIBRARY" "INCLUDES;DEPS" ${ARGN})
  set(incs "")
  foreach(d IN LISTS A_INCLUDES)
    list(APPEND incs "${FSI_OPENFOAM_SRC}/${d}")
  endforeach()
  if(A_LIBRARY)
    set(lib "${FSI_OPENFOAM_LIBDIR}/lib${A_LIBRARY}.so")
    if(NOT EXISTS "${lib}")
      message(WARNING "OpenFOAM: ${lib} is missing; OpenFOAM::${name} not defined")
      return()
    endif()
    add_library(OpenFOAM::${name} SHARED IMPORTED GLOBAL)
    set_target_properties(OpenFOAM::${name} PROPERTIES
      IMPORTED_LOCATION "${lib}"
      IMPORTED_NO_SONAME TRUE)
  else()
    add_library(OpenFOAM::${name} INTERFACE IMPORTED GLOBAL)
  endif()
  set_target_properties(OpenFOAM::${name} PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${incs}"
    INTERFACE_LINK_LIBRARIES "${A_DEPS}")
endfunction()

# Core: flags for every OpenFOAM user. libPstream (Debian's: the system Open MPI one) is named
# on the link line too: the application code calls it directly (wmake links with --add-needed).
_fsi_openfoam_lib(Pstream LIBRARY Pstream)
_fsi_openfoam_lib(OpenFOAM LIBRARY OpenFOAM
  INCLUDES OpenFOAM/lnInclude OSspecific/POSIX/lnInclude)
set_target_properties(OpenFOAM::OpenFOAM PROPERTIES
  INTERFACE_COMPILE_DEFINITIONS "OPENFOAM=1912;WM_DP;WM_LABEL_SIZE=32;NoRepository"
  # -Wno-*: as wmake; the headers do not build clean with -Wextra otherwise.
  INTERFACE_COMPILE_OPTIONS
    "$<$<COMPILE_LANGUAGE:CXX>:-ftemplate-depth-100;-Wno-unused-parameter;-Wno-invalid-offsetof;-Wno-attributes;-Wno-unknown-pragmas>"
  INTERFACE_LINK_OPTIONS "LINKER:--no-as-needed"
  INTERFACE_LINK_LIBRARIES "OpenFOAM::Pstream;Threads::Threads;${CMAKE_DL_LIBS}")
if(NOT TARGET Threads::Threads)
  find_package(Threads REQUIRED)
endif()

_fsi_openfoam_lib(fileFormats LIBRARY fileFormats INCLUDES fileFormats/lnInclude DEPS OpenFOAM::OpenFOAM)
_fsi_openfoam_lib(surfMesh LIBRARY surfMesh INCLUDES surfMesh/lnInclude DEPS OpenFOAM::fileFormats)
_fsi_openfoam_lib(meshTools LIBRARY meshTools INCLUDES meshTools/lnInclude DEPS OpenFOAM::surfMesh)
_fsi_openfoam_lib(finiteVolume LIBRARY finiteVolume INCLUDES finiteVolume/lnInclude
  DEPS OpenFOAM::meshTools)
_fsi_openfoam_lib(transport LIBRARY incompressibleTransportModels
  INCLUDES transportModels transportModels/incompressible/lnInclude
           transportModels/incompressible/singlePhaseTransportModel
  DEPS OpenFOAM::finiteVolume)
_fsi_openfoam_lib(turbulenceModels LIBRARY turbulenceModels
  INCLUDES TurbulenceModels/turbulenceModels/lnInclude DEPS OpenFOAM::finiteVolume)
_fsi_openfoam_lib(turbulence LIBRARY incompressibleTurbulenceModels
  INCLUDES TurbulenceModels/incompressible/lnInclude
  DEPS OpenFOAM::turbulenceModels OpenFOAM::transport)
_fsi_openfoam_lib(lagrangian LIBRARY lagrangian INCLUDES lagrangian/basic/lnInclude
  DEPS OpenFOAM::finiteVolume)
_fsi_openfoam_lib(extrudeModel LIBRARY extrudeModel INCLUDES mesh/extrudeModel/lnInclude
  DEPS OpenFOAM::meshTools)
_fsi_openfoam_lib(dynamicMesh LIBRARY dynamicMesh INCLUDES dynamicMesh/lnInclude
  DEPS OpenFOAM::finiteVolume OpenFOAM::extrudeModel)
_fsi_openfoam_lib(topoChangerFvMesh LIBRARY topoChangerFvMesh INCLUDES topoChangerFvMesh/lnInclude
  DEPS OpenFOAM::dynamicMesh)
_fsi_openfoam_lib(dynamicFvMesh LIBRARY dynamicFvMesh INCLUDES dynamicFvMesh/lnInclude
  DEPS OpenFOAM::dynamicMesh OpenFOAM::topoChangerFvMesh)
_fsi_openfoam_lib(sampling LIBRARY sampling INCLUDES sampling/lnInclude
  DEPS OpenFOAM::dynamicMesh OpenFOAM::lagrangian)
_fsi_openfoam_lib(fvOptions LIBRARY fvOptions INCLUDES fvOptions/lnInclude
  DEPS OpenFOAM::sampling OpenFOAM::turbulence)
_fsi_openfoam_lib(atmosphericModels LIBRARY atmosphericModels INCLUDES atmosphericModels/lnInclude
  DEPS OpenFOAM::turbulence)
_fsi_openfoam_lib(solverLibs
  DEPS OpenFOAM::finiteVolume OpenFOAM::fvOptions OpenFOAM::meshTools OpenFOAM::sampling
       OpenFOAM::turbulence OpenFOAM::dynamicMesh OpenFOAM::dynamicFvMesh
       OpenFOAM::topoChangerFvMesh OpenFOAM::atmosphericModels)

foreach(t Pstream OpenFOAM finiteVolume meshTools turbulence transport dynamicFvMesh solverLibs)
  if(NOT TARGET OpenFOAM::${t})
    _fsi_openfoam_missing("target OpenFOAM::${t} could not be defined (see the warnings above)")
    return()
  endif()
endforeach()

set(FSI_HAVE_OPENFOAM TRUE)
message(STATUS "OpenFOAM v1912: headers ${FSI_OPENFOAM_SRC}, libraries ${FSI_OPENFOAM_LIBDIR}")
