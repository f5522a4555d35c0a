// Episode rollouts live in the env library; see accsim/env/rollout.h.
#pragma once
#include "accsim/env/rollout.h"
