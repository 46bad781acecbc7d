# Optional LP solvers of Minimum_weight_triangulation_2: GLPK and COIN-OR CLP (Debian: libglpk-dev,
# coinor-libclp-dev). Defines the INTERFACE target MDCS::LP_solvers, which links the solvers found and defines
# MDCS_HAS_GLPK=1 / MDCS_HAS_CLP=1; the solver models of the package compile only under these macros. Link it
# next to MDCS::MDCS to use them. Shared by the build tree and the installed MDCSConfig.cmake.
if(NOT TARGET MDCS::LP_solvers)
  add_library(MDCS::LP_solvers INTERFACE IMPORTED)
  set(MDCS_LP_SOLVERS_FOUND "")

  find_path(MDCS_GLPK_INCLUDE_DIR glpk.h)
  find_library(MDCS_GLPK_LIBRARY glpk)
  if(MDCS_GLPK_INCLUDE_DIR AND MDCS_GLPK_LIBRARY)
    target_include_directories(MDCS::LP_solvers SYSTEM INTERFACE ${MDCS_GLPK_INCLUDE_DIR})
    target_link_libraries(MDCS::LP_solvers INTERFACE ${MDCS_GLPK_LIBRARY})
    target_compile_definitions(MDCS::LP_solvers INTERFACE MDCS_HAS_GLPK=1)
    list(APPEND MDCS_LP_SOLVERS_FOUND GLPK)
  endif()

  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(MDCS_CLP QUIET IMPORTED_TARGET GLOBAL clp)
  endif()
  if(MDCS_CLP_FOUND)
    target_link_libraries(MDCS::LP_solvers INTERFACE PkgConfig::MDCS_CLP)
    target_compile_definitions(MDCS::LP_solvers INTERFACE MDCS_HAS_CLP=1)
    list(APPEND MDCS_LP_SOLVERS_FOUND CLP)
  endif()
endif()
