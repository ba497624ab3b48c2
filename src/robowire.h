// Arduino / PlatformIO entry point: the whole library.
#pragma once

#include "../include/robowire/robowire.hpp"
