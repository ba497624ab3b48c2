// The codecs of codecs.hpp in a file built with -O2 (both size macros 0 by default).
#define MIXED_MODES_FILE speed_file
#include "codecs.hpp"
