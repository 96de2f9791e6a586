/* sdfwb
name: X
category: Misc
