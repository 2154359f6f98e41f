#pragma once

#include "modules/register_module_types.h"

void initialize_static_libraries_module(ModuleInitializationLevel p_level);
void uninitialize_static_libraries_module(ModuleInitializationLevel p_level);
