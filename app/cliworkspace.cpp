#include "cliworkspace.h"
