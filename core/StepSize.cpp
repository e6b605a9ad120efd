#include "StepSize.h"
