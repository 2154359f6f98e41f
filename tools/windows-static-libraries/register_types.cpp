#include "register_types.h"

// Nothing to register: the module only links libraries (see config.py).
void initialize_static_libraries_module(ModuleInitializationLevel p_level) {}
void uninitialize_static_libraries_module(ModuleInitializationLevel p_level) {}
