#include "subdiv/version.h"

namespace subdiv {

const char* version() noexcept { return SUBDIV_VERSION_STRING; }

}  // namespace subdiv
