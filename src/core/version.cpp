#include "subdiv/version.h"

namespace subdiv {

const char* version() { return SUBDIV_VERSION_STRING; }

}  // namespace subdiv
