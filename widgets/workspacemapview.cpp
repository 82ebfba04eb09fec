#include "workspacemapview.h"
