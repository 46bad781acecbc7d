# Dependencies of the MDCS::MDCS interface target, shared by the build tree and MDCSConfig.cmake.
include(CMakeFindDependencyMacro)
if(NOT TARGET CGAL::CGAL)
  find_dependency(CGAL 5.5)          # brings GMP and MPFR (CGAL::CGAL links them)
endif()
if(NOT TARGET Boost::boost)
  find_dependency(Boost 1.74)        # Boost.Graph max-flow and Boost.Math quadrature are header-only
endif()
if(NOT TARGET Eigen3::Eigen)
  find_dependency(Eigen3 3.3 NO_MODULE)
endif()
