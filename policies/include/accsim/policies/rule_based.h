// The scripted drivers live in the env library (scenario generation uses
// them to check scenarios, and scenarios may not depend on policies).
#pragma once
#include "accsim/env/scripted_drivers.h"
