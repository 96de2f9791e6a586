/* sdfwb
name: X
category: Misc
type: exactish
*/
