// placeholder, being written
#include "GlTestSupport.h"
