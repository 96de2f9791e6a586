/* sdfwb
name: X
name: Y
*/
