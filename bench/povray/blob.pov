// A blob-heavy scene for timing against POV-Ray: 600 spheres and 100 negative cylinders in one
// blob, filling the view (raycast renders the .pov itself: raycast render bench/povray/blob.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -14> look_at 0 angle 45 }
light_source { <-10, 20, -30> color rgb 1 }
#declare R = seed(7);
blob {
  threshold 0.6
  #declare I = 0;
  #while (I < 600)
    sphere { <-5 + 10 * rand(R), -4 + 8 * rand(R), -3 + 6 * rand(R)>, 0.5 + 0.6 * rand(R), 1 }
    #declare I = I + 1;
  #end
  #declare I = 0;
  #while (I < 100)
    #declare A = <-5 + 10 * rand(R), -4 + 8 * rand(R), -3 + 6 * rand(R)>;
    cylinder { A, A + <rand(R) - 0.5, rand(R) - 0.5, rand(R) - 0.5> * 3, 0.4, -0.7 }
    #declare I = I + 1;
  #end
  pigment { rgb <0.8, 0.5, 0.3> }
  finish { phong 0.6 }
}
