#declare A = array[3] { 1, 2, 3 };
#macro M(X, optional Y) #ifdef(Y) X + Y #else X #end #end
#declare I = 0;
#while (I < 3) #declare I = I + 1; #end
#for (J, 0, 2) sphere { <J, M(1, 2), 0>, 0.5 pigment { rgb <A[J] / 3, 0.5, 0.2> } } #end
#switch (I) #case (3) box { -1, 1 } #break #else cylinder { 0, y, 1 } #end
#declare F = function(a) { a * a + sin(a) }
#debug concat(str(F(2), 0, 3), substr("abc", 2, 1), "\n")
#declare S = spline { cubic_spline 0, <0,0,0>, 1, <1,1,1>, 2, <2,0,0>, 3, <3,1,0> }
camera { location <0, 2, -6> look_at S(1.5) }
light_source { <5, 5, -5> color rgb 1 }
