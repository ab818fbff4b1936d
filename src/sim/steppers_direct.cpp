// The one copy of the direct formulation's out-of-line steppers (see
// sim/steppers.hpp), in a file of its own so that it compiles beside the
// files that use it.
#include "sim/steppers.hpp"

EPVIZ_SIM_INSTANTIATE_STEPPERS(::epviz::physics::DirectSystem)
