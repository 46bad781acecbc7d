// `mdcs geodesics` on a surface used as given (a triangle soup that is not an oriented manifold mesh): the run's
// instantiation for soups, in its own translation unit (see the extern declarations in cmd_geodesics.h).
#include "cmd_geodesics.h"

namespace mdcs_cli {

template Geodesics_run run_geodesics_on<Geo_soup>(const Geo_soup&, const std::string&, const std::vector<std::string>&,
                                                  double, const Geodesics_settings&, const Progress_bar&,
                                                  const Geodesics_run*, bool);

} // namespace mdcs_cli
