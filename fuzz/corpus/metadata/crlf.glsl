/* sdfwb
name: Win
category: Misc
type: conservative
animated: no
author: a
license: CC0-1.0
notes: crlf
  second line
*/
