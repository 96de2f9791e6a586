/* sdfwb
name: Swaying Tree
category: Nature
type: conservative
animated: yes
author: sdfwb authors
license: CC0-1.0
notes: A broadleaf tree bending in the wind (period 4 s): a tapered trunk that forks into
  two branches under a lumpy crown (an ellipsoid with ten
  spheres blended on), on a small mound of earth. The sway
  shifts x by s(y, t) = A sin(wt) ((y + 0.86) / 1.8)^2, a shear whose slope |ds/dy| stays
  below 0.14; the field is divided by 1.14 to keep its gradient under 1. Unions and smooth
  unions make it conservative.
*/
#include "../lib/modelling.glsl"

