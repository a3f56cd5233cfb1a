/* interface: boundary between two dielectrics; shares dielectric's refraction code. */
#include "materials/dielectric.cl"
