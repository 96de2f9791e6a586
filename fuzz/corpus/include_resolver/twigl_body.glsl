vec3 p=vec3(0,0,-3),d=normalize(vec3((FC.xy*2.-r)/r.y,1.));float e,g;
for(int i=0;i<64;i++){vec3 q=p;q.xz*=rotate2D(t);e=length(q)-.5;p+=d*e;g+=.01/abs(e);}
o=vec4(hsv(g,.5,1.),1); // glow
