

  /* sdfwb
Name: Box
CATEGORY: Geometry
type: Exact
animated: true
author: a
license: MIT
	 continued author? no, name is not last
*/
