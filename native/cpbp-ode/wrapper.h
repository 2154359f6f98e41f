#include <ode/ode.h>

/* Added to ODE by tools/build-ode.sh: set a quaternion without renormalising it. */
void dBodySetQuaternionExact(dBodyID b, const dQuaternion q);
