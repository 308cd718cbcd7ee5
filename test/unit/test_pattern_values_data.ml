(* POV-Ray 3.7.0.10's pattern values, printed by the scenes in test/unit/data/pattern_values/
   and written by gen.py there (do not edit: run it again). Each case is a pattern as POV-Ray
   stores it, its warps (for the classic turbulence), its noise generator, how the value was
   printed, the points and POV-Ray's value at each. *)

type route =
  | Raw  (** a pattern function with frequency 0: the raw value, a negative one v as v - floor v *)
  | Wrapped of float * float
      (** a pattern function with this frequency and phase: fmod(v f + p, 1.00001), wrapped *)
  | Exact  (** reconstructed from pigment functions: the raw value *)

type case = {
  label : string;
  pattern : Scene.pattern;
  warps : Scene.warp list;
  gen : int;
  route : route;
  points : Vec.t array;
  values : float array;  (** POV-Ray's, one per point *)
}

let v = Vec.make
let f32 = Precision.f32

let g3 =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
  |]

let frac =
  [|
    v 0.3 0.4 0.0; v (-0.75) 0.1 0.0; v (-1.2) 0.35 0.0; v 0.1 0.62 0.0;
    v (-0.5) (-0.5) 0.0; v 0.28 0.01 0.0; v (-1.9) 0.0 0.0; v 0.45 (-0.3) 0.0;
    v (-0.2) 0.1 0.0; v (-1.0) 0.05 0.0; v 0.2 (-0.1) 0.0; v (-0.1) (-0.7) 0.0;
  |]

let magnet =
  [|
    v 0.5 0.5 0.0; v 1.2 (-0.3) 0.0; v 2.5 0.8 0.0; v (-0.5) 1.1 0.0;
    v 1.9 0.05 0.0; v 0.0 0.0 0.0; v 3.1 (-1.2) 0.0; v 1.05 1.5 0.0;
    v 1.4 0.2 0.0; v 0.9 (-0.9) 0.0;
  |]

let xz =
  [|
    v 2.548 0.37 (-5.718); v 1.649 0.37 4.787; v 4.684 0.37 0.21; v 1.835 0.37 (-1.831);
    v 0.392 0.37 (-5.49); v 2.561 0.37 1.409; v (-3.053) 0.37 (-1.7); v 3.306 0.37 (-0.786);
    v 6.435 0.37 6.598; v 4.737 0.37 (-5.726); v (-5.948) 0.37 (-2.96); v (-1.945) 0.37 2.869;
    v 4.576 0.37 0.877; v 1.949 0.37 1.023; v (-6.523) 0.37 0.373; v (-4.015) 0.37 (-1.163);
    v (-6.877) 0.37 2.181; v 5.743 0.37 (-6.039); v 1.121 0.37 (-6.671); v (-2.074) 0.37 (-4.77);
    v 5.048 0.37 3.192; v 5.551 0.37 (-3.949); v 3.065 0.37 2.793; v 0.15 0.37 5.827;
    v 1.749 0.37 (-3.041); v 3.039 0.37 (-0.263); v (-4.018) 0.37 1.649; v (-6.324) 0.37 (-0.713);
    v 0.795 0.37 (-6.964); v 2.08 0.37 (-5.765); v 2.096 0.37 (-2.224); v (-6.588) 0.37 6.991;
    v (-6.102) 0.37 (-4.812); v 0.08 0.37 (-3.568); v 0.426 0.37 (-0.364); v 1.071 0.37 0.611;
    v (-2.881) 0.37 (-4.04); v 2.724 0.37 (-0.994); v 0.287 0.37 5.823; v (-6.881) 0.37 (-3.117);
  |]

let xz24 =
  [|
    v 2.548 0.37 (-5.718); v 1.649 0.37 4.787; v 4.684 0.37 0.21; v 1.835 0.37 (-1.831);
    v 0.392 0.37 (-5.49); v 2.561 0.37 1.409; v (-3.053) 0.37 (-1.7); v 3.306 0.37 (-0.786);
    v 6.435 0.37 6.598; v 4.737 0.37 (-5.726); v (-5.948) 0.37 (-2.96); v (-1.945) 0.37 2.869;
    v 4.576 0.37 0.877; v 1.949 0.37 1.023; v (-6.523) 0.37 0.373; v (-4.015) 0.37 (-1.163);
    v (-6.877) 0.37 2.181; v 5.743 0.37 (-6.039); v 1.121 0.37 (-6.671); v (-2.074) 0.37 (-4.77);
    v 5.048 0.37 3.192; v 5.551 0.37 (-3.949); v 3.065 0.37 2.793; v 0.15 0.37 5.827;
  |]

let xz200 =
  [|
    v 2.548 0.37 (-5.718); v 1.649 0.37 4.787; v 4.684 0.37 0.21; v 1.835 0.37 (-1.831);
    v 0.392 0.37 (-5.49); v 2.561 0.37 1.409; v (-3.053) 0.37 (-1.7); v 3.306 0.37 (-0.786);
    v 6.435 0.37 6.598; v 4.737 0.37 (-5.726); v (-5.948) 0.37 (-2.96); v (-1.945) 0.37 2.869;
    v 4.576 0.37 0.877; v 1.949 0.37 1.023; v (-6.523) 0.37 0.373; v (-4.015) 0.37 (-1.163);
    v (-6.877) 0.37 2.181; v 5.743 0.37 (-6.039); v 1.121 0.37 (-6.671); v (-2.074) 0.37 (-4.77);
    v 5.048 0.37 3.192; v 5.551 0.37 (-3.949); v 3.065 0.37 2.793; v 0.15 0.37 5.827;
    v 1.749 0.37 (-3.041); v 3.039 0.37 (-0.263); v (-4.018) 0.37 1.649; v (-6.324) 0.37 (-0.713);
    v 0.795 0.37 (-6.964); v 2.08 0.37 (-5.765); v 2.096 0.37 (-2.224); v (-6.588) 0.37 6.991;
    v (-6.102) 0.37 (-4.812); v 0.08 0.37 (-3.568); v 0.426 0.37 (-0.364); v 1.071 0.37 0.611;
    v (-2.881) 0.37 (-4.04); v 2.724 0.37 (-0.994); v 0.287 0.37 5.823; v (-6.881) 0.37 (-3.117);
    v 1.522 (-1.5) (-10.704); v 6.095 (-1.5) (-2.368); v (-4.407) (-1.5) (-7.334); v 11.203 (-1.5) (-10.883);
    v 7.715 (-1.5) 4.909; v 9.54 (-1.5) 4.83; v (-3.673) (-1.5) 1.199; v 10.119 (-1.5) (-11.019);
    v 8.399 (-1.5) 4.162; v (-7.276) (-1.5) 11.202; v (-4.81) (-1.5) (-11.89); v (-5.58) (-1.5) 0.364;
    v (-11.333) (-1.5) 2.202; v (-1.331) (-1.5) (-4.014); v 6.136 (-1.5) 2.841; v 11.168 (-1.5) 8.873;
    v 8.644 (-1.5) 10.393; v 8.399 (-1.5) (-0.319); v (-10.358) (-1.5) (-1.27); v 2.87 (-1.5) 11.266;
    v 3.695 (-1.5) 1.782; v (-9.929) (-1.5) 3.611; v (-11.112) (-1.5) (-8.556); v (-10.963) (-1.5) 5.587;
    v 10.592 (-1.5) 2.262; v (-9.901) (-1.5) 5.738; v (-7.814) (-1.5) 5.026; v 4.234 (-1.5) 10.675;
    v (-8.029) (-1.5) (-6.403); v (-4.339) (-1.5) (-10.163); v 10.69 (-1.5) 2.943; v (-9.45) (-1.5) (-0.529);
    v (-9.63) (-1.5) 11.127; v (-3.371) (-1.5) (-11.939); v 5.766 (-1.5) (-4.066); v 3.589 (-1.5) 6.777;
    v (-10.204) (-1.5) 1.113; v 10.804 (-1.5) (-6.542); v (-6.015) (-1.5) 4.175; v (-10.613) (-1.5) 7.676;
    v 7.249 (-1.5) 10.716; v 7.998 (-1.5) 1.93; v (-0.957) (-1.5) 0.865; v 3.264 (-1.5) 11.44;
    v (-8.343) (-1.5) (-0.131); v (-1.201) (-1.5) (-6.106); v (-8.067) (-1.5) 6.806; v 2.039 (-1.5) 4.542;
    v (-5.826) (-1.5) (-0.49); v (-8.181) (-1.5) (-8.355); v (-8.764) (-1.5) 3.572; v 8.342 (-1.5) 1.712;
    v 6.722 (-1.5) (-10.112); v 0.438 (-1.5) (-8.651); v 0.595 (-1.5) (-6.027); v (-5.909) (-1.5) 10.049;
    v 1.163 (-1.5) (-6.163); v (-0.236) (-1.5) (-5.174); v 7.079 (-1.5) (-2.458); v 8.215 (-1.5) 2.268;
    v 3.635 (-1.5) 2.601; v 2.072 (-1.5) (-10.496); v 6.969 (-1.5) 2.738; v (-6.624) (-1.5) (-0.073);
    v 10.826 (-1.5) 3.685; v 1.254 (-1.5) 0.73; v (-10.336) (-1.5) (-0.087); v (-1.611) (-1.5) 3.426;
    v (-3.31) (-1.5) (-8.542); v 8.378 (-1.5) (-6.036); v (-6.588) (-1.5) (-1.549); v 10.653 (-1.5) 4.786;
    v (-8.605) (-1.5) (-9.707); v 0.01 (-1.5) (-10.516); v (-6.543) (-1.5) (-9.281); v 8.739 (-1.5) 9.252;
    v 8.855 (-1.5) 3.697; v (-11.048) (-1.5) (-5.398); v 7.874 (-1.5) (-11.021); v (-0.039) (-1.5) 7.11;
    v (-5.844) (-1.5) (-3.675); v 3.257 (-1.5) 3.726; v (-8.323) (-1.5) 6.965; v (-10.009) (-1.5) (-8.145);
    v (-4.441) (-1.5) (-7.183); v (-1.062) (-1.5) (-3.561); v 5.425 (-1.5) 7.597; v 6.523 (-1.5) 8.597;
    v (-5.938) (-1.5) 3.769; v 6.927 (-1.5) 8.1; v (-1.898) (-1.5) 9.508; v (-3.38) (-1.5) 9.351;
    v 4.109 (-1.5) (-10.451); v 10.005 (-1.5) 6.564; v 1.09 (-1.5) 10.983; v 9.257 (-1.5) 7.241;
    v 6.331 (-1.5) 5.227; v (-9.208) (-1.5) 2.07; v (-11.847) (-1.5) 0.158; v (-7.848) (-1.5) 4.867;
    v 9.959 (-1.5) (-7.096); v 1.467 (-1.5) (-5.127); v 11.435 (-1.5) (-0.119); v (-7.838) (-1.5) 3.396;
    v (-0.809) (-1.5) 0.425; v (-1.211) (-1.5) (-8.224); v (-9.145) (-1.5) 2.434; v (-8.908) (-1.5) (-2.696);
    v 1.556 (-1.5) 6.96; v (-8.25) (-1.5) (-2.914); v (-9.278) (-1.5) (-6.276); v 11.215 (-1.5) 5.554;
    v (-10.361) (-1.5) 11.579; v (-3.94) (-1.5) 1.675; v 6.96 (-1.5) (-6.681); v (-5.109) (-1.5) (-4.406);
    v 2.379 (-1.5) 11.297; v (-8.246) (-1.5) 11.286; v 1.787 (-1.5) (-0.753); v (-10.267) (-1.5) 5.146;
    v (-10.145) (-1.5) 8.242; v (-5.498) (-1.5) 7.631; v 6.066 (-1.5) (-3.145); v (-5.072) (-1.5) 1.636;
    v (-0.854) (-1.5) (-2.209); v 11.831 (-1.5) (-3.814); v (-3.598) (-1.5) 5.847; v (-1.302) (-1.5) (-5.803);
    v (-1.954) (-1.5) (-9.207); v (-8.022) (-1.5) 7.608; v (-0.788) (-1.5) (-1.144); v (-1.114) (-1.5) (-7.616);
    v (-9.108) (-1.5) (-11.717); v 2.22 (-1.5) (-4.624); v 4.13 (-1.5) (-4.323); v 6.723 (-1.5) 10.293;
    v (-3.069) (-1.5) 2.893; v (-7.993) (-1.5) 2.367; v (-5.196) (-1.5) (-1.242); v 7.771 (-1.5) 8.901;
    v (-2.015) (-1.5) 4.291; v 1.244 (-1.5) (-2.768); v (-9.977) (-1.5) (-10.767); v (-8.5) (-1.5) (-1.929);
    v (-4.992) (-1.5) (-7.493); v (-4.929) (-1.5) (-3.814); v 6.259 (-1.5) 7.323; v 7.068 (-1.5) 1.553;
    v (-10.965) (-1.5) 7.845; v 6.861 (-1.5) (-9.264); v (-6.216) (-1.5) (-1.101); v (-6.937) (-1.5) 11.852;
    v 3.115 (-1.5) 1.701; v (-6.058) (-1.5) (-2.506); v 1.144 (-1.5) 6.569; v (-3.848) (-1.5) (-1.858);
    v (-3.984) (-1.5) (-0.312); v (-4.315) (-1.5) (-6.151); v 1.468 (-1.5) 9.696; v 10.859 (-1.5) 10.685;
  |]

let near_axis =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 0.0005 1.0 0.0002; v 0.0 (-2.0) 0.0; v (-0.0009) 0.5 (-0.3);
  |]

let g3_xz24 =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 2.548 0.37 (-5.718); v 1.649 0.37 4.787; v 4.684 0.37 0.21; v 1.835 0.37 (-1.831);
    v 0.392 0.37 (-5.49); v 2.561 0.37 1.409; v (-3.053) 0.37 (-1.7); v 3.306 0.37 (-0.786);
    v 6.435 0.37 6.598; v 4.737 0.37 (-5.726); v (-5.948) 0.37 (-2.96); v (-1.945) 0.37 2.869;
    v 4.576 0.37 0.877; v 1.949 0.37 1.023; v (-6.523) 0.37 0.373; v (-4.015) 0.37 (-1.163);
    v (-6.877) 0.37 2.181; v 5.743 0.37 (-6.039); v 1.121 0.37 (-6.671); v (-2.074) 0.37 (-4.77);
    v 5.048 0.37 3.192; v 5.551 0.37 (-3.949); v 3.065 0.37 2.793; v 0.15 0.37 5.827;
  |]

let cubic =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 1.0 1.0 1.0; v (-1.0) 0.5 (-1.0); v 0.2 (-3.0) 0.1; v 0.0 0.0 (-2.0);
  |]

let g3_more =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 0.1 0.2 0.3; v 0.5 (-0.7) 0.2;
  |]

let g3_planar =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 0.1 0.2 0.3; v 0.0 (-0.7) 0.0;
  |]

let g3_quilt =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v (-2.0) 3.0 (-1.0);
  |]

let g3_axis =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 0.0 0.0 1.5;
  |]

let g3_cells =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v (-5e-11) 1.0 2.99999999995;
  |]

let crackle =
  [|
    v 0.3 0.4 1.7; v (-1.2) 0.75 0.35; v 2.6 (-0.8) (-3.1); v (-0.45) (-1.9) (-0.7);
    v 5.13 2.2 0.91; v 0.07 0.11 (-0.23); v (-3.7) 4.4 2.9; v 1.01 (-0.33) (-6.25);
    v 10.5 (-20.25) 30.125; v (-0.5) (-0.5) (-0.5); v 0.99999 1e-11 (-1e-11); v 123.4 56.7 (-89.1);
  |]

let plain : case list =
  Scene.
    [
      {
        label = "square";
        pattern = Square;
        warps = [];
        gen = 2;
        route = Exact;
        points = g3_xz24;
        values =
          [|
            1.0; 0.0; 0.0; 2.0; 3.0;
            1.0; 0.0; 2.0; 0.0; 3.0;
            0.0; 3.0; 0.0; 1.0; 0.0;
            2.0; 0.0; 0.0; 1.0; 0.0;
            0.0; 2.0; 3.0; 3.0; 3.0;
            2.0; 2.0; 2.0; 2.0; 3.0;
            3.0; 1.0;
          |];
      };
      {
        label = "triangular";
        pattern = Triangular;
        warps = [];
        gen = 2;
        route = Exact;
        points = g3_xz24;
        values =
          [|
            5.0; 5.0; 2.0; 3.0; 0.0;
            4.0; 0.0; 3.0; 3.0; 1.0;
            4.0; 1.0; 5.0; 3.0; 2.0;
            4.0; 5.0; 0.0; 1.0; 2.0;
            0.0; 0.0; 2.0; 5.0; 5.0;
            4.0; 3.0; 3.0; 0.0; 3.0;
            4.0; 1.0;
          |];
      };
      {
        label = "cubic";
        pattern = Cubic;
        warps = [];
        gen = 2;
        route = Raw;
        points = cubic;
        values =
          [|
            2.0; 3.0; 5.0; 4.0; 0.0;
            5.0; 1.0; 5.0; 0.0; 3.0;
            4.0; 5.0;
          |];
      };
      {
        label = "leopard";
        pattern = Leopard;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.3123332027585193; 0.0009506426762201369; 0.006584531663508455; 0.4558425150205315; 0.051974831460553136;
            0.00025874197365906906; 0.0037013678500727493; 0.034344494829214034;
          |];
      };
      {
        label = "onion";
        pattern = Onion;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.772004514666935; 0.4577379737113252; 0.12431812546025611; 0.07424685126915387; 0.6555282688710875;
            0.2643860813280457; 0.43894401280210005; 0.3396766479056321;
          |];
      };
      {
        label = "radial";
        pattern = Radial;
        warps = [];
        gen = 2;
        route = Raw;
        points = near_axis;
        values =
          [|
            0.7777999438928926; 0.5451672353008665; 1.1389253159862105; 0.34093118408918777; 0.9720584907069575;
            1.2029791303773694; 0.6058021468915982; 1.2245010012944908; 0.25; 0.25;
            0.2504774633968889;
          |];
      };
      {
        label = "planar";
        pattern = Planar;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_planar;
        values =
          [|
            0.6; 0.25; 0.19999999999999996; 0.0; 0.0;
            0.89; 0.0; 0.6699999999999999; 0.8; 0.30000000000000004;
          |];
      };
      {
        label = "boxed";
        pattern = Boxed;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_more;
        values =
          [|
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.77; 0.0; 0.0; 0.7; 0.30000000000000004;
          |];
      };
      {
        label = "spherical";
        pattern = Spherical;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_more;
        values =
          [|
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.7356139186719544; 0.0; 0.0; 0.6258342613226058; 0.11682391336721532;
          |];
      };
      {
        label = "cylindrical";
        pattern = Cylindrical;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_more;
        values =
          [|
            0.0; 0.0; 0.0; 0.16783415114533817; 0.0;
            0.7595836943965738; 0.0; 0.0; 0.683772233983162; 0.4614835192865495;
          |];
      };
      {
        label = "quilted";
        pattern = Quilted { control0 = 1.; control1 = 1. };
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_quilt;
        values =
          [|
            0.12643970891099995; 0.21640568195975432; 0.27167189546973236; 0.20856056779788743; 0.3943773328632083;
            0.40000528027581694; 0.22659256718130316; 0.32351535667986836; 0.5759618941341722;
          |];
      };
      {
        label = "quilted 0.3 2.5";
        pattern = Quilted { control0 = f32 0.3; control1 = f32 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.12158996766313505; 0.2597396949441855; 0.3690406043651566; 0.2624316792405583; 0.5931598330700382;
            0.6054069260090934; 0.2884305846839843; 0.4689594678386448;
          |];
      };
      {
        label = "spiral1 5";
        pattern = Spiral1 5;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_axis;
        values =
          [|
            4.187918088252166; 5.070577958585109; 0.6327561993991389; 6.0674994847837365; 8.06422645839121;
            1.9493952662867131; 11.705312724859061; 0.8112398591747274; 1.5;
          |];
      };
      {
        label = "spiral2 3";
        pattern = Spiral2 3;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_axis;
        values =
          [|
            1.7855017059026004; 1.3334230534680573; 1.0149545171824603; 0.37792447896848813; 1.7068678116991087;
            0.520349654235404; 1.467679740964563; 0.9486113578569202; 1.0;
          |];
      };
      {
        label = "marble";
        pattern = Marble;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.3; 0.8; 2.6; 0.55; 5.13;
            0.07; 0.2999999999999998; 1.01;
          |];
      };
      {
        label = "wood";
        pattern = Wood;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.5; 1.4150971698084907; 2.7202941017470885; 1.9525624189766635; 5.581836615308621;
            0.130384048104053; 5.748912940721924; 1.0625441167311596;
          |];
      };
      {
        label = "mandel exponent 2";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.23333333333333334; 1.0; 1.0;
            1.0; 1.0; 0.2; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 3";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 3; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 0.03333333333333333; 0.0; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 0.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 4";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 4; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.03333333333333333; 1.0; 0.3;
            1.0; 0.0; 1.0; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 5";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 5; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 0.06666666666666667; 0.0; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 0.03333333333333333;
            1.0; 0.26666666666666666;
          |];
      };
      {
        label = "mandel exponent 8";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 8; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.0; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "julia exponent 2";
        pattern = Fractal { fkind = Julia (0.353, 0.288); iterations = 40; exponent = 2; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 0.05; 0.025; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 0.025;
            1.0; 1.0;
          |];
      };
      {
        label = "julia exponent 3";
        pattern = Fractal { fkind = Julia (0.353, 0.288); iterations = 40; exponent = 3; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.025; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "julia exponent 4";
        pattern = Fractal { fkind = Julia (0.353, 0.288); iterations = 40; exponent = 4; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.0; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 0.025;
            1.0; 1.0;
          |];
      };
      {
        label = "julia exponent 6";
        pattern = Fractal { fkind = Julia (0.353, 0.288); iterations = 40; exponent = 6; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.0; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 0.025;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 1 (as 2)";
        pattern = Fractal { fkind = Mandel; iterations = 25; exponent = 1; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.28; 1.0; 1.0;
            1.0; 1.0; 0.24; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 40 (as 2)";
        pattern = Fractal { fkind = Mandel; iterations = 25; exponent = 40; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.28; 1.0; 1.0;
            1.0; 1.0; 0.24; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel interior 0";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.3; 1.3; 0.23333333333333334; 1.3; 1.3;
            1.3; 1.3; 0.2; 1.3; 1.3;
            1.3; 1.3;
          |];
      };
      {
        label = "julia exponent 3 interior 0";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 0; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.8; 0.15; 0.0; 0.8; 0.8;
            0.8; 0.0; 0.8; 0.8; 0.05;
            0.8; 0.8;
          |];
      };
      {
        label = "mandel interior 1";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 1; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.3018723367676013; 0.2648500755144314; 0.23333333333333334; 0.1949395004974422; 0.2343102123996426;
            0.30489734354442105; 0.01417089981061741; 0.2; 0.23436083290515933; 0.06470789877222947;
            0.2906888370749727; 0.11985407794480757;
          |];
      };
      {
        label = "julia exponent 3 interior 1";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 1; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.31679627167535473; 0.15; 0.0; 0.27373302257583537; 0.282842712474619;
            0.22414281161795044; 0.0; 0.34406727850441693; 0.1788854381999832; 0.05;
            0.1788854381999832; 0.14918202358193153;
          |];
      };
      {
        label = "mandel interior 2";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 2; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.010669917764252084; 1.837544824625754; 0.23333333333333334; 0.3121740866830307; 0.240121182058053;
            1.0138600044122692; 0.28722237899223113; 0.2; 0.7726313469694479; 0.6967897930610021;
            0.2802380893680717; 0.882537200168142;
          |];
      };
      {
        label = "julia exponent 3 interior 2";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 2; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.9066053680715657; 0.15; 0.0; 0.9058150274596152; 0.9072550529092613;
            0.9076527793425758; 0.0; 0.9064787989187778; 0.9075643639041386; 0.05;
            0.9074182803864999; 0.9090362007626203;
          |];
      };
      {
        label = "mandel interior 3";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 3; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.5196296285433879; 0.46776675142116786; 0.23333333333333334; 0.5764084986429595; 0.5831569188702759;
            0.3756338968437098; 0.0; 0.2; 0.096310712387694; 0.0646805569648358;
            0.7714745708659188; 0.10320177395097418;
          |];
      };
      {
        label = "julia exponent 3 interior 3";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 3; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.40067619772314433; 0.15; 0.0; 0.39746364967058095; 0.39637393215366185;
            0.3987088724229852; 0.0; 0.3978140316795593; 0.3989557484558937; 0.05;
            0.39876715755783243; 0.39865347479388497;
          |];
      };
      {
        label = "mandel interior 4";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 4; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            8.757472699684787e-05; 2.5973622942376093; 0.23333333333333334; 0.3639265284848638; 0.444166013812962;
            0.7907016219591128; 0.39080918231499584; 0.2; 0.039766541831482746; 1.3064283411307582;
            0.060410297486667194; 0.010613468726414738;
          |];
      };
      {
        label = "julia exponent 3 interior 4";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 4; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.010903196591309665; 0.15; 0.0; 0.01108851131554131; 0.010752031513579896;
            0.010660011453938729; 0.0; 0.010932768814592998; 0.010680433525558149; 0.05;
            0.010714218508240954; 0.010343015964622896;
          |];
      };
      {
        label = "mandel interior 5";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 5; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.20770380835395333; 0.1683121028731636; 0.23333333333333334; 0.25557442869833125; 0.13366011868132444;
            0.108539095736916; 0.0; 0.2; 0.007135194862019319; 0.003218134191754898;
            0.04017220904685847; 0.6186515832651381;
          |];
      };
      {
        label = "julia exponent 3 interior 5";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 5; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.20067676927734535; 0.15; 0.0; 0.19747169101182285; 0.19639036761369463;
            0.1987109561860103; 0.0; 0.19782000475143174; 0.19895711153250292; 0.05;
            0.19876905743344142; 0.19865574120654833;
          |];
      };
      {
        label = "mandel interior 6";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 6; exterior_type = 1; ifactor = 1.3; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.20777117352856628; 2.1662830984405557; 0.23333333333333334; 0.5355179121482265; 0.47532628315283365;
            0.7167711126285412; 0.3006224479346122; 0.2; 0.037724842424698354; 1.0081630119846459;
            0.08664166865198708; 0.6268157899777649;
          |];
      };
      {
        label = "julia exponent 3 interior 6";
        pattern = Fractal { fkind = Julia ((-0.2), 0.6); iterations = 20; exponent = 3; interior_type = 6; exterior_type = 1; ifactor = 0.8; efactor = 1.0 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            0.21430576501648244; 0.15; 0.0; 0.2113323301562495; 0.2098304070056695;
            0.21203597050343373; 0.0; 0.211485965769673; 0.2123076534394506; 0.05;
            0.2121618305687426; 0.21158451116232696;
          |];
      };
      {
        label = "mandel exterior 0";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 0; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.7; 1.0; 1.0;
            1.0; 1.0; 0.7; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 0";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 0; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 2.5; 1.0; 1.0;
            1.0; 2.5; 1.0; 1.0; 2.5;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 1";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.23333333333333334; 1.0; 1.0;
            1.0; 1.0; 0.2; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 1";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 1; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.0; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 0.06666666666666667;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 2";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 2; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.21806396632106573; 1.0; 1.0;
            1.0; 1.0; 0.08575379680703199; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 2";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 2; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 1.8147145781249974; 1.0; 1.0;
            1.0; 0.7820652500000733; 1.0; 1.0; 0.2904497967654365;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 3";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 3; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.3741026635157316; 1.0; 1.0;
            1.0; 1.0; 0.5914526096429418; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 3";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 3; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 11.780368892578124; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 302.06645960345;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 4";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 4; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 4.536137183033446; 1.0; 1.0;
            1.0; 1.0; 1.1940658857896542; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 4";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 4; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 1.3172756000237549; 1.0; 1.0;
            1.0; 20833.370296622088; 1.0; 1.0; 1153.8863132135095;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 5";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 5; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.5596392511687165; 1.0; 1.0;
            1.0; 1.0; 8.28728647370828; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 5";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 5; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 55.510836498088935; 1.0; 1.0;
            1.0; 0.0; 1.0; 1.0; 36497.658406945084;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 6";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 6; ifactor = 1.0; efactor = 0.7 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 1.8886618288993702; 1.0; 1.0;
            1.0; 1.0; 2.576227212737369; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exponent 7 exterior 6";
        pattern = Fractal { fkind = Mandel; iterations = 15; exponent = 7; interior_type = 0; exterior_type = 6; ifactor = 1.0; efactor = 2.5 };
        warps = [];
        gen = 2;
        route = Raw;
        points = frac;
        values =
          [|
            1.0; 1.0; 11.919323816613161; 1.0; 1.0;
            1.0; 228.21793474999993; 1.0; 1.0; 306.8042727870596;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 7, 5";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 7; ifactor = 1.0; efactor = 5.0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.4; 1.0; 1.0;
            1.0; 1.0; 0.2; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 7, 3.7";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 7; ifactor = 1.0; efactor = 3.7 };
        warps = [];
        gen = 2;
        route = Exact;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.27027027027027023; 1.0; 1.0;
            1.0; 1.0; 0.0; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 8, 4";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 8; ifactor = 1.0; efactor = 4.0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.5; 1.0; 1.0;
            1.0; 1.0; 0.25; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "mandel exterior 8, 6.5";
        pattern = Fractal { fkind = Mandel; iterations = 30; exponent = 2; interior_type = 0; exterior_type = 8; ifactor = 1.0; efactor = 6.5 };
        warps = [];
        gen = 2;
        route = Exact;
        points = frac;
        values =
          [|
            1.0; 1.0; 0.0; 1.0; 1.0;
            1.0; 1.0; 0.9230769230769231; 1.0; 1.0;
            1.0; 1.0;
          |];
      };
      {
        label = "magnet 1 mandel interior 0 exterior 1";
        pattern = Fractal { fkind = Magnet_mandel 1; iterations = 20; exponent = 0; interior_type = 0; exterior_type = 1; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            1.5; 1.5; 0.5; 0.3; 0.05;
            1.5; 0.25; 0.2; 1.5; 1.5;
          |];
      };
      {
        label = "magnet 1 julia interior 0 exterior 1";
        pattern = Fractal { fkind = Magnet_julia (1, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 0; exterior_type = 1; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            1.5; 0.2; 1.5; 1.5; 1.5;
            1.5; 0.2; 1.5; 1.5; 1.5;
          |];
      };
      {
        label = "magnet 1 mandel interior 1 exterior 2";
        pattern = Fractal { fkind = Magnet_mandel 1; iterations = 20; exponent = 0; interior_type = 1; exterior_type = 2; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.30000000000000004; 0.12679299171982425; 139.11901932118917; 0.8999064064479463; 0.2038327349461042;
            0.375; 0.8998790441464873; 106.80029923137081; 0.052083333333333426; 0.25846364573070996;
          |];
      };
      {
        label = "magnet 1 julia interior 1 exterior 2";
        pattern = Fractal { fkind = Magnet_julia (1, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 1; exterior_type = 2; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.3597784445479516; 0.9000721294456365; 0.23990250060794582; 0.10089295361899114; 0.34446820518680255;
            0.0; 109.34815199006471; 0.18376043236424142; 0.369023169882478; 0.36997051946890935;
          |];
      };
      {
        label = "magnet 1 mandel interior 4 exterior 6";
        pattern = Fractal { fkind = Magnet_mandel 1; iterations = 20; exponent = 0; interior_type = 4; exterior_type = 6; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.0014207625329572733; 0.014414341848669514; 158.0538602059868; 0.8999064760767472; 950.5602940730421;
            1.0740636684996798; 0.899879808298478; 468.5021342276229; 0.03236168421750091; 0.11076280422189627;
          |];
      };
      {
        label = "magnet 1 julia interior 4 exterior 6";
        pattern = Fractal { fkind = Magnet_julia (1, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 4; exterior_type = 6; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.059662884397683996; 0.9000726238610299; 0.05964041651097682; 0.059662925526463004; 0.05967324524355009;
            0.05966293397635496; 117.8279109108793; 0.059662756424856286; 0.05966418215257856; 0.05966326046355526;
          |];
      };
      {
        label = "magnet 1 mandel interior 6 exterior 3";
        pattern = Fractal { fkind = Magnet_mandel 1; iterations = 20; exponent = 0; interior_type = 6; exterior_type = 3; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.10928511512133028; 0.013416585539811517; 75.01280683406141; 0.000354003973038423; 832.5088285244339;
            0.7160424456664533; 0.001172727295682203; 0.8334231227289592; 0.023848041634656376; 0.14615338110991583;
          |];
      };
      {
        label = "magnet 1 julia interior 6 exterior 3";
        pattern = Fractal { fkind = Magnet_julia (1, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 6; exterior_type = 3; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.07151096126864967; 0.9990565916703025; 0.07154691040745007; 0.07151094022901386; 0.07152179141859334;
            0.07151098645973833; 43.890753536249676; 0.07151076176347862; 0.071511845477543; 0.0715111898132596;
          |];
      };
      {
        label = "magnet 2 mandel interior 0 exterior 1";
        pattern = Fractal { fkind = Magnet_mandel 2; iterations = 20; exponent = 0; interior_type = 0; exterior_type = 1; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            1.5; 1.5; 0.15; 0.1; 1.5;
            0.5; 0.1; 0.25; 1.5; 1.5;
          |];
      };
      {
        label = "magnet 2 julia interior 0 exterior 1";
        pattern = Fractal { fkind = Magnet_julia (2, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 0; exterior_type = 1; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            1.5; 0.05; 1.5; 1.5; 0.15;
            1.5; 0.25; 1.5; 0.1; 1.5;
          |];
      };
      {
        label = "magnet 2 mandel interior 1 exterior 2";
        pattern = Fractal { fkind = Magnet_mandel 2; iterations = 20; exponent = 0; interior_type = 1; exterior_type = 2; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.576923076923077; 0.23928391326273318; 0.8999998272158798; 0.8999978442624964; 0.009463109511213359;
            0.893271673432683; 0.8999993657853483; 0.9000006348738473; 0.02577874434024499; 0.5841131938171626;
          |];
      };
      {
        label = "magnet 2 julia interior 1 exterior 2";
        pattern = Fractal { fkind = Magnet_julia (2, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 1; exterior_type = 2; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.533196195436449; 0.8950142717129969; 0.5342216855239815; 0.39008099190805506; 0.8999204635468511;
            0.0; 0.9003353667559196; 0.5255075900502725; 0.8999380458618312; 0.2427593691844933;
          |];
      };
      {
        label = "magnet 2 mandel interior 4 exterior 6";
        pattern = Fractal { fkind = Magnet_mandel 2; iterations = 20; exponent = 0; interior_type = 4; exterior_type = 6; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.0007257801661755551; 0.018347517542344136; 0.8999998272159081; 0.8999979048655394; 4.93299631604508e-05;
            0.893271673432683; 0.8999993657854872; 0.9000006348768204; 0.014162834266547675; 0.39615019346180047;
          |];
      };
      {
        label = "magnet 2 julia interior 4 exterior 6";
        pattern = Fractal { fkind = Magnet_julia (2, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 4; exterior_type = 6; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.12207387216458931; 0.8950150543518248; 0.1220738721331028; 0.12207387216503468; 0.8999204650837891;
            0.12207387216366977; 0.9003353868194829; 0.12207387216810646; 0.8999381618410078; 0.1220738721774324;
          |];
      };
      {
        label = "magnet 2 mandel interior 6 exterior 3";
        pattern = Fractal { fkind = Magnet_mandel 2; iterations = 20; exponent = 0; interior_type = 6; exterior_type = 3; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.25642711970794385; 0.044302628641554445; 0.9999997746312173; 0.999669719483195; 7.684177421344034e-05;
            0.0; 0.9999995000973627; 0.9999976866797401; 0.020643842474162684; 0.4007760421495081;
          |];
      };
      {
        label = "magnet 2 julia interior 6 exterior 3";
        pattern = Fractal { fkind = Magnet_julia (2, (0.4, (-0.2))); iterations = 20; exponent = 0; interior_type = 6; exterior_type = 3; ifactor = 1.5; efactor = 0.9 };
        warps = [];
        gen = 2;
        route = Raw;
        points = magnet;
        values =
          [|
            0.1496520312401085; 0.9988163841612667; 0.14965203122263146; 0.14965203124221832; 5.259509396785604e-05;
            0.14965203123981963; 0.9998099266674231; 0.1496520312398203; 0.9995431103410987; 0.14965203125898532;
          |];
      };
      {
        label = "tiling 1";
        pattern = Tiling 1;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.758; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.42599999999999993; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "tiling 2";
        pattern = Tiling 2;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.8492888392262803; 0.5872242613892613; 0.4372435565298213; 0.22212834288620475; 0.6606940442979086;
            0.7475134707118172; 0.9655045423776363; 0.24020268841695402; 0.6187141522263013; 0.6118152827595946;
            0.6569567968012927; 0.7114179223050364; 0.9873276278413964; 0.8187413492380258; 0.6923516504077307;
            0.6570832738649304; 0.5184018742051477; 0.7703817243638497; 0.9725036457639938; 0.6799607840345148;
            0.3141958814934287; 0.8309562130298322; 0.547539301846625; 0.4857799814320508; 0.4952778313943479;
            0.8091568792031284; 0.09589881221261409; 0.9123492580677967; 0.9586654507268909; 0.6568486037563851;
            0.5680539973554557; 0.4482557319046737; 0.8802094953404797; 0.8800284790628308; 0.5796890040299525;
            0.7182389855251385; 0.5485049124739119; 0.8498861675744879; 0.35108938250880917; 0.40079842187187276;
          |];
      };
      {
        label = "tiling 3";
        pattern = Tiling 3;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.7739332588394205; 0.827836392083892; 0.2078653347947324; 0.8381925143293072; 0.6664794667765687;
            0.6212702060677258; 0.44825681356645436; 0.36139193474913767; 0.6334643858302746; 0.4356385379303039;
            0.6414351952019379; 0.0671268834575548; 0.4809914417620945; 0.2281120238570386; 0.10752747561159515;
            0.5296875446013019; 0.7956985943461395; 0.4598548269084501; 0.9587554686459908; 0.7419411760517716;
            0.33635308887992854; 0.7464343195447483; 0.1623820944601252; 0.6786699721480762; 0.48991674709152216;
            0.3307353188046929; 0.45507589084053907; 0.3685238871016949; 0.9379981760903364; 0.1273635471827113;
            0.2179595019834083; 0.39123280428597873; 0.8203142430107193; 0.969978640702877; 0.6762332469775356;
            0.5773584782877079; 0.17975736871086834; 0.7783414972765359; 0.8876340737632136; 0.877901183596095;
          |];
      };
      {
        label = "tiling 4";
        pattern = Tiling 4;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.6985776784525608; 0.7704485227785227; 0.5150257738807145; 0.7842566857724096; 0.32138808859581713;
            0.49502694142363435; 0.9259818304894554; 0.8151892463321836; 0.251285847773698; 0.9141847172404052;
            0.521913593602584; 0.37432831077985396; 0.9746552556827927; 0.6374826984760515; 0.4767033008154602;
            0.31416654772986075; 0.7275981257948527; 0.9464731025446; 0.9450072915279877; 0.3599215680690294;
            0.5898041185065712; 0.6619124260596643; 0.5498427926135003; 0.5715599628641013; 0.022888674422608113;
            0.6183137584062568; 0.9401011877873855; 0.8246985161355932; 0.9173309014537818; 0.3136972075127703;
            0.23994600264454424; 0.854977072381305; 0.35241899068095794; 0.7600569581256615; 0.2723109959700474;
            0.4364779710502773; 0.329980350104352; 0.7044553297020479; 0.8501787650176179; 0.8372015781281268;
          |];
      };
      {
        label = "tiling 5";
        pattern = Tiling 5;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.2328592261508536; 0.5901495075928409; 0.5368290376865477; 0.5947522285908031; 0.8517686519006972;
            0.1650089804745448; 0.9770030282517574; 0.5681351256113027; 0.8370952825912331; 0.3047282390801351;
            0.5073045312008613; 0.8076119482033577; 0.32488508522759757; 0.21249423282535052; 0.7949011002718205;
            0.790972242045023; 0.7451993752649506; 0.5135878162425664; 0.31500243050932925; 0.1199738560230098;
            0.19660137283552373; 0.22063747535322142; 0.45169286789774993; 0.5238533209547005; 0.6621852209295653;
            0.5914379194687525; 0.31336706259579516; 0.6082328387118644; 0.9724436338179272; 0.1045657358375901;
            0.07998200088151475; 0.9516590241271017; 0.5868063302269864; 0.986657173645723; 0.8561036653233491;
            0.1454926570167591; 0.5243366083159414; 0.5665907783829919; 0.6167262550058726; 0.7870671927093759;
          |];
      };
      {
        label = "tiling 6";
        pattern = Tiling 6;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.718; 0.2869999999999999; 0.79; 0.835; 0.009999999999999787;
            0.09099999999999997; 0.44700000000000006; 0.786; 0.5650000000000004; 0.2370000000000001;
            0.45999999999999996; 0.9450000000000003; 0.5759999999999996; 0.9770000000000001; 0.127;
            0.33699999999999974; 0.8769999999999998; 0.7430000000000003; 0.879; 0.42600000000000016;
            0.30799999999999983; 0.44899999999999984; 0.43500000000000005; 0.85; 0.4590000000000001;
            0.9609999999999999; 0.4820000000000002; 0.21300000000000008; 0.795; 0.9199999999999999;
            0.4039999999999999; 0.9909999999999997; 0.3979999999999997; 0.9199999999999999; 0.13600000000000012;
            0.42900000000000005; 0.45999999999999996; 0.7240000000000002; 0.8230000000000004; 0.383;
          |];
      };
      {
        label = "tiling 7";
        pattern = Tiling 7;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.6824660940672627; 0.5581067811865474; 0.500000000001; 0.6148533213566644; 0.5378817433796305;
            0.7981067811865474; 0.7496086937588515; 0.9792673862422577; 0.8198112267284637; 0.6904660940672627;
            0.9704800820635759; 0.500000000001; 0.6698932188134525; 0.845219120621257; 0.565506858075828;
            0.3095617587574858; 0.500000000001; 0.2093036072312176; 0.989770926787756; 0.500000000001;
            0.5706796564403578; 0.925678282274302; 0.5209111806311533; 0.7914660940672626; 0.7064751801064719;
            0.500000000001; 0.9070394333889303; 0.946637413135377; 0.5878932188134526; 0.7294660940672624;
            0.500000000001; 0.500000000001; 0.933533905932737; 0.9466796564403577; 0.500000000001;
            0.9822468247692255; 0.6804632406047914; 0.7868932188134525; 0.7874660940672631; 0.5455568568003826;
          |];
      };
      {
        label = "tiling 8";
        pattern = Tiling 8;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.31209530167593047; 0.2698834712496108; 0.7575129202736907; 0.9595561807264915; 0.8752923751883742;
            0.13046959343189024; 0.8082904101988092; 0.2409279564994251; 0.999912032042629; 0.5189529990448268;
            0.9399556053376128; 0.32989856548176344; 0.8579718671126856; 0.30677522095061066; 0.6666667000000001;
            0.6666667000000001; 0.6666667000000001; 0.32176586526606105; 0.8602812681894441; 0.801479542022807;
            0.06953485420736745; 0.41615531736550554; 0.9156775602680801; 0.7356616113351894; 0.7101701982001414;
            0.22049021253646195; 0.41606731607480096; 0.24568259140112994; 0.7632864229655869; 0.47391967804803636;
            0.46934339615476883; 0.5278120115204962; 0.7529821194108776; 0.9076239902629933; 0.4508221646516904;
            0.9180162951084067; 0.27453878418649685; 0.8522276981843571; 0.7540488186585529; 0.8625906692662028;
          |];
      };
      {
        label = "tiling 9";
        pattern = Tiling 9;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.6666667; 0.551890928055928; 0.7575128869403572; 0.5587950095528714; 0.6666667;
            0.6666667; 0.2988378757109696; 0.6666667; 0.42230959055351613; 0.6666667;
            0.6666667; 0.7114179223050364; 0.6666667; 0.6666667; 0.07168498374106347;
            0.6666667; 0.6666667; 0.7703817243638498; 0.9725036457639938; 0.679960784034515;
            0.7949020592532855; 0.6666667; 0.6666667; 0.7857799814320504; 0.3266111647276814;
            0.8091568792031284; 0.9700505938936926; 0.6666667; 0.6253321173935591; 0.6666667;
            0.6666667; 0.26082186952398584; 0.6762094953404792; 0.6466524271352515; 0.4508221646516905;
            0.7182389855251387; 0.6666667; 0.8498861675744878; 0.9250893825088088; 0.9186007890640634;
          |];
      };
      {
        label = "tiling 10";
        pattern = Tiling 10;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.8780000000000001; 0.8940000000000001; 0.6120000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.8700000000000001; 0.6539999999999999; 0.9180000000000001;
            0.4740000000000002; 0.29800000000000004; 0.6479999999999997; 0.9280000000000008; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.8519999999999999;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "tiling 11";
        pattern = Tiling 11;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.47866666666666663; 0.19133333333333327; 0.5266666666666667; 0.2233333333333333; 0.7386666666666667;
            0.7273333333333333; 0.9646666666666667; 0.524; 0.7100000000000003; 0.484;
            0.9733333333333333; 0.5793333333333335; 0.5846666666666667; 0.31800000000000006; 0.418;
            0.32333333333333353; 0.9179999999999998; 0.9740000000000002; 0.4473333333333335; 0.9506666666666668;
            0.5386666666666665; 0.7006666666666668; 0.6233333333333334; 0.5666666666666667; 0.6393333333333334;
            0.6406666666666666; 0.32133333333333347; 0.7840000000000001; 0.6426666666666669; 0.5099999999999998;
            0.5173333333333332; 0.6606666666666664; 0.9319999999999998; 0.6133333333333334; 0.4240000000000001;
            0.6193333333333334; 0.9733333333333333; 0.8160000000000002; 0.548666666666667; 0.922;
          |];
      };
      {
        label = "tiling 12";
        pattern = Tiling 12;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.47866666666666663; 0.19133333333333327; 0.5266666666666667; 0.2233333333333333; 0.7386666666666667;
            0.7273333333333333; 0.9646666666666667; 0.5239999999999997; 0.7100000000000003; 0.4913333333333334;
            0.64; 0.6300000000000002; 0.5846666666666666; 0.31800000000000006; 0.7513333333333332;
            0.32333333333333353; 0.5459999999999999; 0.9740000000000002; 0.586; 0.9506666666666668;
            0.5386666666666665; 0.6326666666666666; 0.9566666666666667; 0.9; 0.6393333333333334;
            0.6406666666666666; 0.32133333333333347; 0.7840000000000001; 0.8633333333333333; 0.5099999999999998;
            0.9359999999999999; 0.7253333333333334; 0.9319999999999998; 0.6133333333333333; 0.7573333333333334;
            0.6193333333333334; 0.9206666666666665; 0.6626666666666665; 0.8820000000000002; 0.5886666666666667;
          |];
      };
      {
        label = "tiling 13";
        pattern = Tiling 13;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.6090179002337616; 0.1798935487200044; 0.4686767679344334; 0.0633879246364198; 0.5165694996615863;
            0.7478672888249976; 0.7882706627166272; 0.7943819168358731; 0.26635715075275596; 0.6014754279011049;
            0.5602847498307926; 0.6284141930343932; 0.17315647053253036; 0.17086815537677502; 0.3516677725101098;
            0.0; 0.6104001469761862; 0.9187810075275422; 0.043854216939388145; 0.2887192855745327;
            0.5031457505076204; 0.900199656488701; 0.6332656531387032; 0.9865694996615865; 0.4662510378822784;
            0.9650485835025401; 0.0; 0.9694305003384129; 0.2504668119422595; 0.5647058752794045;
            0.5813333333333331; 0.12210736739069954; 0.7530207717337518; 0.9245752766734349; 0.6253333333333334;
            0.5760563244066407; 0.9504338178687419; 0.9015451626028742; 0.5860971670050801; 0.3945975507220414;
          |];
      };
      {
        label = "tiling 14";
        pattern = Tiling 14;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.765410740140257; 0.9079363292320026; 0.48120606076066; 0.8380329547818519; 0.5099416997969518;
            0.048720373294998606; 0.07296239762997629; 0.2766291501015239; 0.9598144904516536; 0.7608852567406629;
            0.7361708498984756; 0.5770485158206359; 0.9038940823195183; 0.902521093226065; 0.41100066350606584;
            0.8000002; 0.7662400881857117; 0.3512686045165253; 0.8263127301636329; 0.9732317713447196;
            0.5018874503045723; 0.14011979389322066; 0.7799593918832219; 0.39194169979695187; 0.679750622729367;
            0.37902915010152405; 0.8000002; 0.1816583002030478; 0.9502802871653557; 0.7388235251676427;
            0.5488; 0.8732646204344198; 0.05181246304025109; 0.3547451660040609; 0.7752000000000001;
            0.5456337946439844; 0.17026029072124516; 0.1409270975617245; 0.5516583002030481; 0.6367585304332248;
          |];
      };
      {
        label = "tiling 15";
        pattern = Tiling 15;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.71800001; 0.50000001; 0.7900000100000001; 0.33499999999999996; 0.5100000099999998;
            0.09099999999999997; 0.44700000000000006; 0.2859999999999996; 0.50000001; 0.50000001;
            0.45999999999999996; 0.50000001; 0.5760000099999997; 0.9770000100000001; 0.62700001;
            0.9850000100000004; 0.81900001; 0.7430000100000004; 0.379; 0.9260000100000002;
            0.8080000099999999; 0.9490000099999999; 0.50000001; 0.35; 0.7490000100000002;
            0.46099999999999985; 0.50000001; 0.21300000000000008; 0.9640000100000005; 0.7650000099999997;
            0.90400001; 0.9910000099999997; 0.8120000100000003; 0.9200000100000001; 0.6360000100000002;
            0.9290000100000001; 0.96000001; 0.9940000099999998; 0.3230000000000004; 0.8830000100000001;
          |];
      };
      {
        label = "tiling 16";
        pattern = Tiling 16;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.1856967317655472; 0.7955006696526; 0.2601405843723886; 0.7374278045069533; 0.4662437460065793;
            0.5970726272720353; 0.6666667; 0.9075946231660921; 0.6666667; 0.17717703790166425;
            0.6666667; 0.3092656802179221; 0.1457287707112316; 0.7810204054293872; 0.3270324904944798;
            0.7661913677428395; 0.0; 0.913514794675829; 0.6666667; 0.0;
            0.05579749220256399; 0.6666667; 0.7022398402258762; 0.057037488849531526; 0.1982040365793929;
            0.8448939283657483; 0.8153500555144418; 0.3297333989700069; 0.6666667; 0.5911033422537079;
            0.19250663073262633; 0.5330470098124122; 0.7529820860775439; 0.0; 0.21528454800811403;
            0.871828240239903; 0.6666667; 0.16798465903699644; 0.14013447572850954; 0.034379997247896976;
          |];
      };
      {
        label = "tiling 17";
        pattern = Tiling 17;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.25951519921610694; 0.8977503348263; 0.29673712551952763; 0.8687139022534766; 0.7331218730032897;
            0.7985363136360176; 0.8333335000000001; 0.9537973115830459; 0.8333335000000001; 0.42192201895083215;
            0.8333335000000001; 0.4879663401089611; 0.2395312186889491; 0.8905102027146935; 0.49684974524723996;
            0.8830956838714198; 0.16666683333333332; 0.9567573973379145; 0.8333335000000001; 0.3333335;
            0.1945655794346153; 0.8333335000000001; 0.8511199201129381; 0.19518557775809908; 0.09910201828969645;
            0.9224469641828742; 0.9076750277572209; 0.3315335328183368; 0.8333335000000001; 0.6288850044601872;
            0.42958681536631316; 0.766523504906206; 0.8764910430387719; 0.3333335; 0.440975774004057;
            0.9359141201199516; 0.8333335000000001; 0.25065916285183154; 0.23673407119758808; 0.18385683195728184;
          |];
      };
      {
        label = "tiling 18";
        pattern = Tiling 18;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.718; 0.649; 0.79; 0.33499999999999996; 0.10799999999999998;
            0.09099999999999997; 0.20000000000000018; 0.694; 0.5650000000000004; 0.22599999999999998;
            0.45999999999999996; 0.9450000000000003; 0.5759999999999996; 0.9490000000000001; 0.627;
            0.9850000000000003; 0.31899999999999995; 0.9610000000000003; 0.879; 0.42600000000000016;
            0.30799999999999983; 0.9489999999999998; 0.935; 0.85; 0.7490000000000001;
            0.9609999999999999; 0.4820000000000002; 0.21300000000000008; 0.795; 0.9199999999999999;
            0.4039999999999999; 0.49099999999999966; 0.3979999999999997; 0.9199999999999999; 0.13600000000000012;
            0.929; 0.45999999999999996; 0.7240000000000002; 0.8230000000000004; 0.8810000000000002;
          |];
      };
      {
        label = "tiling 19";
        pattern = Tiling 19;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.666667; 0.5518909280559291; 0.13857688986315578; 0.5587950095528722; 0.666667;
            0.41418013737848386; 0.666667; 0.2409279564994249; 0.7556429238868506; 0.29042569195353635;
            0.4276234634679584; 0.666667; 0.3206609611747297; 0.15207468257135906; 0.07168498374106343;
            0.35312502973420107; 0.530465729564093; 0.3065698846056326; 0.6391703124306606; 0.6799607840345147;
            0.7949020592532855; 0.49762287969649893; 0.7749213963067504; 0.45244664809871776; 0.666667;
            0.22049021253646162; 0.9700505938936925; 0.9123492580677967; 0.9586654507268921; 0.666667;
            0.1453063346556057; 0.666667; 0.5468761620071462; 0.6466524271352511; 0.4508221646516901;
            0.38490565219180506; 0.666667; 0.5188943315176909; 0.5917560491754746; 0.9186007890640631;
          |];
      };
      {
        label = "tiling 20";
        pattern = Tiling 20;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.8492888392262801; 0.666667; 0.13857688986315578; 0.5587950095528722; 0.4443196445177126;
            0.41418013737848386; 0.2988378757109697; 0.9075946231660915; 0.666667; 0.29042569195353635;
            0.4276234634679584; 0.04475125563836946; 0.9303361860793014; 0.15207468257135906; 0.07168498374106343;
            0.35312502973420107; 0.530465729564093; 0.7703817243638501; 0.6391703124306606; 0.6799607840345147;
            0.22423539258661887; 0.49762287969649893; 0.666667; 0.7857799814320511; 0.3266111647276821;
            0.666667; 0.30338392722702606; 0.666667; 0.6253321173935588; 0.666667;
            0.666667; 0.26082186952398634; 0.5468761620071462; 0.666667; 0.666667;
            0.38490565219180506; 0.666667; 0.5188943315176909; 0.9250893825088089; 0.666667;
          |];
      };
      {
        label = "tiling 21";
        pattern = Tiling 21;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43008008407835224; 0.7463836353412961; 0.9198040612524778; 0.882131397208144; 0.042776511858956;
            0.6418552719732968; 0.9931152422706632; 0.8333335000000001; 0.48012685483050793; 0.7424879842882137;
            0.8296693057374506; 0.78765673930987; 0.8675225840941363; 0.9101970280798968; 0.9887606653350379;
            0.11870259367857537; 0.2658444899157624; 0.8821721088999196; 0.40029625087771775; 0.6666668333333333;
            0.8999072140294282; 0.5805974759120601; 0.043255415820516764; 0.1414171292870114; 0.8026600855175395;
            0.13677526610549015; 0.12043464448614431; 0.6666668333333333; 0.4817773258334337; 0.7446532862646089;
            0.8333335000000001; 0.06699920698197498; 0.8333335000000001; 0.6096864883245936; 0.9450243926626097;
            0.7594401242036833; 0.6331363504083162; 0.5280865539612676; 0.821034377273499; 0.21989508380945566;
          |];
      };
      {
        label = "tiling 22";
        pattern = Tiling 22;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.6666667; 0.7829746295488945; 0.970933021243476; 0.9689746295488945; 0.8342773382103146;
            0.6666667; 0.6666667; 0.6666667; 0.9393753781240273; 0.6666667;
            0.7367869781100002; 0.6666667; 0.6666667; 0.6666667; 0.8723298970935719;
            0.6666667; 0.6666667; 0.6666667; 0.6666667; 0.6666667;
            0.6666667; 0.6666667; 0.6666667; 0.6666667; 0.6666667;
            0.6666667; 0.7140508409022107; 0.6666667; 0.6666667; 0.6666667;
            0.976702166605874; 0.7559592797286525; 0.6666667; 0.4406270233508129; 0.6666667;
            0.6666667; 0.6666667; 0.6666667; 0.6666667; 0.932927965634331;
          |];
      };
      {
        label = "tiling 23";
        pattern = Tiling 23;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.666667; 0.6043415875862954; 0.806667; 0.9793167308103744; 0.5946666666666667;
            0.666667; 0.875350602522959; 0.7726560163664952; 0.8912828590977897; 0.5079322565748301;
            0.5850855428394385; 0.666667; 0.08199999999999985; 0.8953506025229592; 0.21233680290642779;
            0.666667; 0.666667; 0.7299698078284175; 0.8770986111206577; 0.666667;
            0.6399661282874153; 0.2784956712975489; 0.666667; 0.666667; 0.2152059112591985;
            0.23219179509320834; 0.2625653555138554; 0.8927708268581703; 0.2596008551753957; 0.666667;
            0.09468360252295908; 0.99328285909779; 0.666667; 0.10936720504591853; 0.666667;
            0.4122474534532848; 0.7498470470687248; 0.5813502691896261; 0.666667; 0.012615859097789209;
          |];
      };
      {
        label = "tiling 24";
        pattern = Tiling 24;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.8000002; 0.7626049525517773; 0.8840002; 0.9875900384862246; 0.3568;
            0.8000002; 0.9252103615137754; 0.8635936098198972; 0.9347697154586738; 0.30475935394489806;
            0.5510513257036631; 0.8000002; 0.04919999999999991; 0.9372103615137755; 0.12740208174385667;
            0.8000002; 0.8000002; 0.8379818846970505; 0.9262591666723946; 0.8000002;
            0.38397967697244917; 0.16709740277852933; 0.8000002; 0.8000002; 0.1291235467555191;
            0.139315077055925; 0.15753921330831325; 0.9356624961149022; 0.15576051310523745; 0.8000002;
            0.05681016151377545; 0.995969715458674; 0.8000002; 0.06562032302755112; 0.8000002;
            0.44734847207197087; 0.8499082282412349; 0.34881016151377564; 0.8000002; 0.007569515458673526;
          |];
      };
      {
        label = "tiling 25";
        pattern = Tiling 25;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz200;
        values =
          [|
            0.6493696898346798; 0.25112063553131203; 0.16666766666666666; 0.16666766666666666; 0.16666766666666666;
            0.27867968744191324; 0.6689468537590018; 0.7602091288430911; 0.16666766666666666; 0.4885269330242586;
            0.1681727100678372; 0.8270849158398254; 0.43814077605594254; 0.2619766273876683; 0.2528785743456882;
            0.3333343333333333; 0.0; 0.42881083952290977; 0.16666766666666666; 0.3654867222164361;
            0.16666766666666666; 0.6968949706166339; 0.11376122969211497; 0.16666766666666666; 0.7543707389743197;
            0.8328852369101587; 0.3333343333333333; 0.16666766666666666; 0.27227258771919816; 0.5826107845856285;
            0.25842435428579363; 0.4406029460105307; 0.3447584061968389; 0.48393621040392903; 0.046404815617275816;
            0.4927240813590803; 0.4934253011986263; 0.16666766666666666; 0.16666766666666666; 0.9821891558370193;
            0.16666766666666666; 0.053168457991891155; 0.7732086460541187; 0.783712631853688; 0.32442698535205877;
            0.4107453907106837; 0.3333343333333333; 0.11403192589380842; 0.16666766666666666; 0.9466683263130931;
            0.7618945043514068; 0.3268518111230214; 0.3980235293851189; 0.13078614809213807; 0.30685378222533566;
            0.16666766666666666; 0.3141019903149008; 0.3403473929402833; 0.22399987120017983; 0.16666766666666666;
            0.4198633250995551; 0.12675611705516718; 0.3886183187052667; 0.6666676666666667; 0.16666766666666666;
            0.24917057078902216; 0.08759253143977867; 0.2045124021871218; 0.3568700281430274; 0.2117130659216318;
            0.06161527549128222; 0.5938099262477247; 0.500001; 0.48259178178355017; 0.6712636569309631;
            0.9396997545326424; 0.16666766666666666; 0.2554152988419786; 0.3327335243551099; 0.0;
            0.3937731501163355; 0.16666766666666666; 0.3333343333333333; 0.16666766666666666; 0.16666766666666666;
            0.16666766666666666; 0.3333343333333333; 0.6508307146732968; 0.17073754530350893; 0.2536720041081434;
            0.17684982910398062; 0.28307340906138134; 0.3333343333333333; 0.20292983332700157; 0.18031777534238638;
            0.3333343333333333; 0.6466436912281736; 0.3179747935697164; 0.09358902922718931; 0.16666766666666666;
            0.39824035717864203; 0.3720461355698347; 0.47678906942494187; 0.7328350975092974; 0.0;
            0.9749041052720064; 0.6301890903711526; 0.05764282877130508; 0.6492023170679034; 0.6035093037067475;
            0.07037183922594889; 0.3333343333333333; 0.17060173217081298; 0.08718423895800435; 0.0;
            0.24237712892942792; 0.8314059914759058; 0.6974126111870758; 0.16666766666666666; 0.0;
            0.16666766666666666; 0.954888186049846; 0.3333343333333333; 0.1303495826617407; 0.7479273331222122;
            0.0; 0.24419534458610437; 0.0; 0.16666766666666666; 0.34710361823666447;
            0.286082224787562; 0.3107799821605409; 0.48494941684581333; 0.13487375999730017; 0.16666766666666666;
            0.014841972762659139; 0.1916559500854296; 0.31841777175972175; 0.0; 0.4866192037190648;
            0.09740098927002569; 0.5917002393832663; 0.931918776760532; 0.231240033994846; 0.3764524832017647;
            0.42874717302448273; 0.6914286816569188; 0.3071952810594115; 0.16666766666666666; 0.2931180234401053;
            0.47680720707524493; 0.32485245350269604; 0.16666766666666666; 0.3333343333333333; 0.1956128729250207;
            0.16666766666666666; 0.24645646497586937; 0.16666766666666666; 0.2838209532546026; 0.18839416681324164;
            0.1590629523160528; 0.22603236979517582; 0.31879994025728436; 0.18957842072191175; 0.3314186626305526;
            0.3333456772337645; 0.019486761662458163; 0.16666766666666666; 0.21083842310761503; 0.310596057019533;
            0.3696882920599172; 0.3333343333333333; 0.2932421708456896; 0.6626461861287403; 0.16666766666666666;
            0.3333343333333333; 0.2794698164489249; 0.3081544852265178; 0.9076308266682365; 0.3333343333333333;
            0.4763515594123591; 0.29467707882297767; 0.3048256719989031; 0.7998360160533438; 0.6666676666666667;
            0.5964367789346191; 0.49815505953573574; 0.322499749269566; 0.02750740502704707; 0.0;
            0.16666766666666666; 0.2213812883085855; 0.0057714410225131185; 0.06555435240958975; 0.16666766666666666;
            0.4369862147678286; 0.01010942572698198; 0.10923904735817344; 0.48762500983249224; 0.3811970401323853;
          |];
      };
      {
        label = "tiling 26";
        pattern = Tiling 26;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz200;
        values =
          [|
            0.38716464518257326; 0.3014679094458258; 0.791730782278772; 0.34390497340300596; 0.0933563183488263;
            0.21045285604959385; 0.2510168627114766; 0.3010681295920966; 0.3230234945276057; 0.14672746318941488;
            0.3819524436578818; 0.47284160818705273; 0.3834007459044672; 0.0; 0.6484957352475011;
            0.23291123844615347; 0.25925335527524795; 0.6841792548470257; 0.9012968585384448; 0.665397051980581;
            0.022358518276211492; 0.9575954224849667; 0.0; 0.2684076180846077; 0.24751886031400294;
            0.0; 0.0; 0.1951572293811138; 0.12179365489755589; 0.059757463189415605;
            0.0; 0.3294440958988225; 0.9777880141471545; 0.0; 0.40168895929877135;
            0.7295358528793143; 0.4599523205813683; 0.15637398934608593; 0.2765623756295664; 0.46432575556347877;
            0.9063515653378172; 0.8455090193581608; 0.2814738900344536; 0.0; 0.34212364942280005;
            0.16595364942279783; 0.13205425291607675; 0.7409550736211695; 0.23950409683842633; 0.0675724613599254;
            0.07337022698788676; 0.021404970384118704; 0.9115671482493358; 0.4432197226777826; 0.06523534956358584;
            0.7374586218859491; 0.9341651939514508; 0.12506374944295434; 0.31929977590916025; 0.13412834981203292;
            0.24533847462697705; 0.6207992066267904; 0.7027644111173077; 0.0; 0.5055472374599361;
            0.11996746318941359; 0.4467886516749556; 0.18728348127052552; 0.36591113942069553; 0.0;
            0.8685805908398446; 0.6824090959159965; 0.27834985391197087; 0.17169904228297733; 0.9169103192390089;
            0.22665867164034637; 0.23791204735082916; 0.06259594105820576; 0.1479223795168787; 0.9372245327198374;
            0.12397381376661848; 0.0; 0.1938450534703347; 0.6501591479980856; 0.3163943655432784;
            0.0424315936191334; 0.589121253737241; 0.9691429863408492; 0.03641679259326186; 0.08756586185712117;
            0.0; 0.8275927256605922; 0.8981956996613011; 0.024031262351352778; 0.0;
            0.32195820037617473; 0.850293248567648; 0.13330509409180846; 0.4288668247114018; 0.1769442429877498;
            0.4278679969379999; 0.3854261862333842; 0.022239204028441373; 0.8372099999999998; 0.16801187667478185;
            0.4643513331830767; 0.3059900000000032; 0.9666507933732085; 0.4671240267466531; 0.4080386675800798;
            0.9773471439504078; 0.4835328464695167; 0.21844774557957658; 0.4300261862333872; 0.31666526048004384;
            0.24282712741091306; 0.42801427196659453; 0.12237633393994185; 0.0; 0.4920246071398205;
            0.2536209707294669; 0.3863086191223356; 0.2583714465446582; 0.3048306384780137; 0.0;
            0.3568726821913311; 0.2161095258657959; 0.0; 0.45358134232410907; 0.4051806384780098;
            0.8030422175715745; 0.0; 0.43086053805714786; 0.39884349452760653; 0.7042657883134806;
            0.3936294979098178; 0.260319945473128; 0.055497901867850974; 0.9663113417751656; 0.4093296010449339;
            0.24807971984366944; 0.0782396077155349; 0.9967561743430754; 0.39975079337320474; 0.38778735443326195;
            0.7668955301868281; 0.9223825458036882; 0.8827153568255433; 0.44042823700831785; 0.0;
            0.1713946906978452; 0.9697125368105856; 0.8449610680759136; 0.1613172526673588; 0.7763444242570166;
            0.0; 0.08533904707392304; 0.4757148448968359; 0.23079378892791091; 0.23950100503804994;
            0.08852063847800884; 0.23837070008066985; 0.09698308325328148; 0.28333714395040893; 0.21102829471778184;
            0.02112968076099342; 0.829991019621599; 0.2785368410778264; 0.9203923046944094; 0.0;
            0.16128204395388124; 0.3641904043864841; 0.2837702984175515; 0.3798320725494398; 0.272351206564729;
            0.9517049047742258; 0.742080317291526; 0.2259368247113971; 0.0; 0.0;
            0.49419819745002264; 0.0; 0.010243813766613263; 0.9880161163841549; 0.9480295258657978;
            0.021129680760991476; 0.4842618455173079; 0.15053164550309384; 0.7807308557504246; 0.03529101061653345;
            0.0; 0.0; 0.8946901354354404; 0.46151326565576895; 0.4796344472002523;
            0.4825427527849455; 0.0; 0.38866030104236604; 0.0; 0.6949425605569819;
          |];
      };
      {
        label = "tiling 27";
        pattern = Tiling 27;
        warps = [];
        gen = 2;
        route = Exact;
        points = xz200;
        values =
          [|
            0.2420261584792463; 0.8473133031387269; 0.8398246911974229; 0.8799507226210144; 0.13100371478346617;
            0.7773156124433186; 0.0; 0.21692075945022044; 0.4714372029229149; 0.08143947075344782;
            0.09250081489836587; 0.6420984851444678; 0.0; 0.0; 0.3432362700689565;
            0.2597047138515891; 0.0; 0.25710915931489825; 0.0853855180607333; 0.14018958492384265;
            0.12314693487975203; 0.0; 0.07009435848977075; 0.29566656675411346; 0.11003433896504533;
            0.8337473448542211; 0.3110737510492501; 0.01322272298005045; 0.7557372300027765; 0.03855098679632807;
            0.6728210488811486; 0.3688291774155674; 0.19239271185208562; 0.8706314658257718; 0.0;
            0.29199192872050705; 0.9308535759093058; 0.8548929038919978; 0.4787522635931552; 0.0;
            0.42797703326004366; 0.9831867840117544; 0.3953794936667247; 0.0; 0.3785807452343958;
            0.9686955422213135; 0.422761828443963; 0.3678858822456945; 0.44711174657417674; 0.21550363208985823;
            0.6634737286564485; 0.7458230998359017; 0.3286984113037751; 0.4747201550370514; 0.9622157440518802;
            0.0; 0.386997858677829; 0.3933129120122796; 0.7637868386135178; 0.10136383134457339;
            0.0; 0.3395205807386248; 0.7714025972857476; 0.0; 0.11972717430499152;
            0.20772527210362324; 0.0; 0.0; 0.0; 0.15266765253185788;
            0.7690117647342616; 0.8991806870276888; 0.0; 0.7567328431470343; 0.2175621391213614;
            0.38370644500462747; 0.8474923122853613; 0.9599337149153531; 0.2292247879912595; 0.4517207585122588;
            0.3164983681355624; 0.25050785598037334; 0.6117066431025638; 0.29288345064316; 0.3587929146766068;
            0.0; 0.18005765426918402; 0.4762685444077687; 0.2861480897698441; 0.18280590785056128;
            0.9720079865721593; 0.20302595896605075; 0.4217045350119458; 0.10012880638341587; 0.8351037814801054;
            0.01390174390855703; 0.32509264117131553; 0.4684490913450703; 0.0; 0.11943460716454901;
            0.44452485109696066; 0.5982767569925349; 0.1445152443858599; 0.0; 0.3909755957627047;
            0.9725833885666004; 0.0; 0.32687316089763563; 0.47471580665805013; 0.0;
            0.48257818292734617; 0.16763029402433782; 0.6494161481225182; 0.446184667370464; 0.2529148039837662;
            0.2572725684379346; 0.26281943748556474; 0.2095778820118634; 0.4070400344784089; 0.14420954072207504;
            0.31051526707748955; 0.7445883316390398; 0.46494728763661564; 0.08023314899553585; 0.3708103782884812;
            0.10002301359023702; 0.7816660337130497; 0.08519267605677577; 0.4643004237074085; 0.42707649897366395;
            0.0; 0.48143989398190373; 0.0; 0.0; 0.37959994197362995;
            0.0; 0.3156673023132647; 0.3967832875334049; 0.22902299763260742; 0.0;
            0.9821230800818638; 0.8316624015556487; 0.31749699013932275; 0.0; 0.27415259409558235;
            0.32072444097061836; 0.4403061103777451; 0.4097989412750666; 0.45418465754320275; 0.49681940756929877;
            0.12969685237919504; 0.0; 0.6688976842808692; 0.2664825987609455; 0.11448447433317999;
            0.0; 0.18109331321248; 0.2110886484477042; 0.0; 0.0;
            0.07772207396092967; 0.798786616837088; 0.6869251952487734; 0.2961614461341241; 0.277758169761114;
            0.22517520970388455; 0.36924980451133704; 0.09624739138286503; 0.15962651319476046; 0.8301183957540785;
            0.7424834402756102; 0.8955518047565489; 0.394226257966513; 0.38683919377281595; 0.3249202825746607;
            0.16955895725433873; 0.30163960245248556; 0.33797563182412294; 0.448220712021465; 0.3155699252582702;
            0.050212568660621404; 0.8162850650255504; 0.12333920861551412; 0.4907834567209487; 0.0;
            0.13171129128086045; 0.22882734819232198; 0.33613221663235143; 0.3313648878344418; 0.9501039690970692;
            0.04269488502449148; 0.9029650222084401; 0.40911097926521534; 0.987467797202636; 0.0;
            0.14828043166773813; 0.32120412152262917; 0.008034478686786695; 0.0; 0.4926126758184592;
          |];
      };
      {
        label = "pavement 3 1 1";
        pattern = Pavement { side = 3; tile = 1; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.24254041213545152; 0.8965136271329087; 0.7227838694982753; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.1342537669151096; 0.961982883524189; 0.4562240477140772; 0.2150549512231903;
            0.05937508920260359; 0.5913971886922791; 0.9197096538169002; 0.9175109372919816; 0.48388235210354325;
            0.6727061777598571; 0.4928686390894964; 0.3247641889202504; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.7370477742033898; 0.8759963521806727; 0.2547270943654226;
            0.4359190039668166; 0.7824656085719575; 0.6406284860214386; 0.939957281405754; 0.35246649395507135;
            0.15471695657541595; 0.3595147374217367; 0.5566829945530718; 0.775268147526427; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 2 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.25986651767884084; 0.0; 0.4157306695894648; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.2669287716605492; 0.0;
            0.0; 0.1342537669151096; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.3247641889202504; 0.18532011140769555; 0.9798334941830443;
            0.6614706376093858; 0.8021517816810796; 0.4699044515932195; 0.8759963521806727; 0.2547270943654226;
            0.4359190039668166; 0.7824656085719575; 0.6406284860214386; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.5566829945530718; 0.17146370494714602; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 3 3 1";
        pattern = Pavement { side = 3; tile = 3; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.7227838694982753; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.961982883524189; 0.4562240477140772; 0.0;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.10902187458396317; 0.0;
            0.38470617775985694; 0.0; 0.3247641889202504; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.4699044515932195; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.5566829945530718; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 3 4 1";
        pattern = Pavement { side = 3; tile = 4; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.25986651767884084; 0.0; 0.4157306695894648; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.7227838694982753; 0.0; 0.0;
            0.0; 0.06149246616978088; 0.961982883524189; 0.4562240477140772; 0.0;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.3247641889202504; 0.18532011140769555; 0.0;
            0.6614706376093858; 0.8021517816810796; 0.4699044515932195; 0.8759963521806727; 0.2547270943654226;
            0.4359190039668166; 0.7824656085719575; 0.6406284860214386; 0.6400854371884923; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.5566829945530718; 0.17146370494714602; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 3 4 2";
        pattern = Pavement { side = 3; tile = 4; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.6763850286586144; 0.0;
            0.0; 0.8965136271329087; 0.2793919347491379; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.1342537669151096; 0.961982883524189; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.10902187458396317; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.18532011140769555; 0.9798334941830443;
            0.4274706376093851; 0.9101517816810781; 0.4699044515932195; 0.4470018239096638; 0.0;
            0.0; 0.7824656085719575; 0.0; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.5496585027234636; 0.17146370494714602; 0.0;
          |];
      };
      {
        label = "pavement 3 4 3";
        pattern = Pavement { side = 3; tile = 4; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.0;
            0.24254041213545152; 0.8965136271329087; 0.2793919347491379; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.23085482690844916; 0.10902187458396317; 0.0;
            0.05741235551971402; 0.4928686390894964; 0.0; 0.0; 0.9798334941830443;
            0.08894127521877093; 0.7123035633621577; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.0; 0.939957281405754; 0.35246649395507135;
            0.0; 0.0; 0.5496585027234636; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 3 5 1";
        pattern = Pavement { side = 3; tile = 5; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.24254041213545152; 0.888972745734183; 0.7227838694982753; 0.0; 0.0;
            0.0; 0.06149246616978088; 0.961982883524189; 0.4562240477140772; 0.0;
            0.0; 0.0; 0.9197096538169002; 0.10902187458396317; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246; 0.0;
            0.4274706376093851; 0.7123035633621577; 0.4699044515932195; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.0; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.5566829945530718; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 3 5 2";
        pattern = Pavement { side = 3; tile = 5; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.24254041213545152; 0.888972745734183; 0.7227838694982753; 0.0; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.9197096538169002; 0.10902187458396317; 0.0;
            0.38470617775985694; 0.0; 0.3247641889202504; 0.35733994429615246; 0.0;
            0.4274706376093851; 0.7123035633621577; 0.4699044515932195; 0.8759963521806727; 0.2547270943654226;
            0.4359190039668166; 0.7824656085719575; 0.02862848602143675; 0.6400854371884923; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.5566829945530718; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 3 5 3";
        pattern = Pavement { side = 3; tile = 5; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.25986651767884084; 0.0; 0.4157306695894648; 0.6572299426827712; 0.0;
            0.0; 0.888972745734183; 0.7227838694982753; 0.2669287716605492; 0.8712770758606078;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.0;
            0.38470617775985694; 0.0; 0.3247641889202504; 0.0; 0.0;
            0.6614706376093858; 0.8021517816810796; 0.4699044515932195; 0.8759963521806727; 0.2547270943654226;
            0.4359190039668166; 0.7824656085719575; 0.6406284860214386; 0.6400854371884923; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.5566829945530718; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 3 5 4";
        pattern = Pavement { side = 3; tile = 5; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.0; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.7227838694982753; 0.0; 0.0;
            0.28287039040387596; 0.1342537669151096; 0.961982883524189; 0.4562240477140772; 0.2150549512231903;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.10902187458396317; 0.0;
            0.05741235551971402; 0.4928686390894964; 0.03261790553987476; 0.18532011140769555; 0.0;
            0.08894127521877093; 0.9101517816810781; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.4359190039668166; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.0;
            0.0; 0.0; 0.5566829945530718; 0.17146370494714602; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 6 1";
        pattern = Pavement { side = 3; tile = 6; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.7227838694982753; 0.0; 0.0;
            0.0; 0.06149246616978088; 0.961982883524189; 0.4562240477140772; 0.0;
            0.0; 0.0; 0.9197096538169002; 0.10902187458396317; 0.0;
            0.38470617775985694; 0.0; 0.3247641889202504; 0.35733994429615246; 0.0;
            0.4274706376093851; 0.7123035633621577; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.6400854371884923; 0.0;
            0.11656608684916825; 0.0; 0.5566829945530718; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 3 6 2";
        pattern = Pavement { side = 3; tile = 6; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.06149246616978088; 0.961982883524189; 0.4562240477140772; 0.0;
            0.0; 0.0; 0.3111451730915491; 0.10902187458396317; 0.48388235210354325;
            0.6727061777598571; 0.0; 0.3247641889202504; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.7123035633621577; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.4359190039668166; 0.7824656085719575; 0.02862848602143675; 0.6400854371884923; 0.35246649395507135;
            0.0; 0.0; 0.5496585027234636; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 3 6 3";
        pattern = Pavement { side = 3; tile = 6; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.25986651767884084; 0.6556727841677841; 0.2725386608210716; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.7227838694982753; 0.0; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246; 0.0;
            0.08894127521877093; 0.9101517816810781; 0.4699044515932195; 0.32299817609033654; 0.2547270943654226;
            0.4359190039668166; 0.7824656085719575; 0.02862848602143675; 0.5800427185942463; 0.0;
            0.11656608684916825; 0.0; 0.5566829945530718; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 3 6 4";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.6406284860214386; 0.6400854371884923; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.10634149727653541; 0.775268147526427; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 6 5";
        pattern = Pavement { side = 3; tile = 6; number = 5; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.6556727841677841; 0.2725386608210716; 0.6572299426827712; 0.0;
            0.0; 0.888972745734183; 0.7227838694982753; 0.0; 0.8712770758606078;
            0.0; 0.06149246616978088; 0.961982883524189; 0.4562240477140772; 0.2150549512231903;
            0.0; 0.5913971886922791; 0.9197096538169002; 0.9175109372919816; 0.0;
            0.05741235551971402; 0.0; 0.0; 0.35733994429615246; 0.0;
            0.4274706376093851; 0.9101517816810781; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.6400854371884923; 0.0;
            0.0; 0.0; 0.5566829945530718; 0.775268147526427; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 6 6";
        pattern = Pavement { side = 3; tile = 6; number = 6; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.0;
            0.24254041213545152; 0.888972745734183; 0.2793919347491379; 0.0; 0.0;
            0.28287039040387596; 0.0; 0.961982883524189; 0.4562240477140772; 0.0;
            0.0; 0.0; 0.3111451730915491; 0.9175109372919816; 0.03988235210354418;
            0.05741235551971402; 0.4928686390894964; 0.0; 0.35733994429615246; 0.0;
            0.4274706376093851; 0.7123035633621577; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.6400854371884923; 0.0;
            0.15471695657541595; 0.0; 0.10634149727653541; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 3 6 7";
        pattern = Pavement { side = 3; tile = 6; number = 7; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6763850286586144; 0.0;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.2669287716605492; 0.8712770758606078;
            0.0; 0.06149246616978088; 0.961982883524189; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.0;
            0.38470617775985694; 0.18686863908949536; 0.3247641889202504; 0.18532011140769555; 0.0;
            0.08894127521877093; 0.8021517816810796; 0.7370477742033898; 0.4470018239096638; 0.0;
            0.0; 0.0; 0.0; 0.939957281405754; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.5566829945530718; 0.17146370494714602; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 6 8";
        pattern = Pavement { side = 3; tile = 6; number = 8; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6763850286586144; 0.0;
            0.0; 0.8965136271329087; 0.2793919347491379; 0.2669287716605492; 0.8712770758606078;
            0.0; 0.06149246616978088; 0.7529914417620958; 0.4562240477140772; 0.0;
            0.05937508920260359; 0.0; 0.23085482690844916; 0.19151093729198176; 0.0;
            0.38470617775985694; 0.18686863908949536; 0.3247641889202504; 0.0; 0.0;
            0.08894127521877093; 0.8021517816810796; 0.7370477742033898; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.0; 0.939957281405754; 0.0;
            0.0; 0.3595147374217367; 0.5496585027234636; 0.0; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 6 9";
        pattern = Pavement { side = 3; tile = 6; number = 9; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.0; 0.8712770758606078;
            0.0; 0.1342537669151096; 0.961982883524189; 0.4562240477140772; 0.0;
            0.0; 0.5913971886922791; 0.9197096538169002; 0.9175109372919816; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.0; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.8021517816810796; 0.4699044515932195; 0.8759963521806727; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.6400854371884923; 0.35246649395507135;
            0.0; 0.0; 0.5566829945530718; 0.775268147526427; 0.7558023671921901;
          |];
      };
      {
        label = "pavement 3 6 10";
        pattern = Pavement { side = 3; tile = 6; number = 10; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.5478665176788411; 0.0; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.7227838694982753; 0.0; 0.0;
            0.0; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.0; 0.0; 0.9197096538169002; 0.19151093729198176; 0.0;
            0.38470617775985694; 0.18686863908949536; 0.03261790553987476; 0.35733994429615246; 0.0;
            0.4274706376093851; 0.8021517816810796; 0.7370477742033898; 0.32299817609033654; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.6400854371884923; 0.0;
            0.11656608684916825; 0.0; 0.5566829945530718; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 3 6 11";
        pattern = Pavement { side = 3; tile = 6; number = 11; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.7227838694982753; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.961982883524189; 0.4562240477140772; 0.0;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.10902187458396317; 0.0;
            0.38470617775985694; 0.0; 0.3247641889202504; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.4699044515932195; 0.8759963521806727; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.0; 0.3595147374217367; 0.5566829945530718; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 3 6 12";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 4 1 1";
        pattern = Pavement { side = 4; tile = 1; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.758; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.42599999999999993; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 2 1";
        pattern = Pavement { side = 4; tile = 2; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.12199999999999989; 0.8940000000000001; 0.3879999999999999; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.758; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.4980000000000002;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.5900000000000001; 0.8399999999999999;
            0.8079999999999998; 0.17600000000000016; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 3 1";
        pattern = Pavement { side = 4; tile = 3; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 3 2";
        pattern = Pavement { side = 4; tile = 3; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.8940000000000001; 0.3879999999999999; 0.13000000000000078; 0.45199999999999996;
            0.8960000000000008; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.5900000000000001; 0.5299999999999994;
            0.8079999999999998; 0.17600000000000016; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 4 1";
        pattern = Pavement { side = 4; tile = 4; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.9640000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 4 2";
        pattern = Pavement { side = 4; tile = 4; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.42599999999999993; 0.5900000000000001; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 4 3";
        pattern = Pavement { side = 4; tile = 4; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.6539999999999999; 0.4980000000000002;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.17600000000000016; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 4 4";
        pattern = Pavement { side = 4; tile = 4; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.0; 0.3999999999999999; 0.0; 0.13000000000000078; 0.45199999999999996;
            0.8960000000000008; 0.8900000000000001; 0.0; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.0; 0.8520000000000003;
            0.0; 0.8979999999999997; 0.0; 0.7; 0.4980000000000002;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.0; 0.8399999999999999;
            0.8079999999999998; 0.0; 0.7959999999999994; 0.84; 0.272;
            0.0; 0.9199999999999999; 0.0; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 4 5";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7; 0.4980000000000002;
            0.9219999999999997; 0.9640000000000004; 0.42599999999999993; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 5 1";
        pattern = Pavement { side = 4; tile = 5; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 2";
        pattern = Pavement { side = 4; tile = 5; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 3";
        pattern = Pavement { side = 4; tile = 5; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.0; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.0; 0.0;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.6539999999999999; 0.9180000000000001;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.0; 0.8399999999999999;
            0.5519999999999996; 0.0; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 5 4";
        pattern = Pavement { side = 4; tile = 5; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6619999999999999; 0.019999999999999574;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 5";
        pattern = Pavement { side = 4; tile = 5; number = 5; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.15199999999999925; 0.8980000000000001; 0.045999999999999375;
            0.6739999999999999; 0.6379999999999999; 0.48600000000000065; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.5900000000000001; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 6";
        pattern = Pavement { side = 4; tile = 5; number = 6; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.019999999999999574;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.48600000000000065; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.10200000000000031; 0.8700000000000001; 0.7; 0.4980000000000002;
            0.9219999999999997; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 7";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.4980000000000002;
            0.9219999999999997; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.8399999999999999;
            0.5519999999999996; 0.17600000000000016; 0.6240000000000006; 0.84; 0.14800000000000002;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 5 8";
        pattern = Pavement { side = 4; tile = 5; number = 8; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.019999999999999574;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.045999999999999375;
            0.9700000000000006; 0.6379999999999999; 0.48600000000000065; 0.758; 0.8520000000000003;
            0.9039999999999999; 0.10200000000000031; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 9";
        pattern = Pavement { side = 4; tile = 5; number = 9; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.48600000000000065; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.10200000000000031; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.42600000000000005; 0.766;
          |];
      };
      {
        label = "pavement 4 5 10";
        pattern = Pavement { side = 4; tile = 5; number = 10; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.8520000000000003;
            0.9039999999999999; 0.10200000000000031; 0.8700000000000001; 0.6539999999999999; 0.4980000000000002;
            0.9219999999999997; 0.29800000000000004; 0.3520000000000003; 0.5900000000000001; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.42600000000000005; 0.766;
          |];
      };
      {
        label = "pavement 4 5 11";
        pattern = Pavement { side = 4; tile = 5; number = 11; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.019999999999999574;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.8960000000000008; 0.7380000000000004; 0.15199999999999925; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.5900000000000001; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 5 12";
        pattern = Pavement { side = 4; tile = 5; number = 12; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.019999999999999574;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.48600000000000065; 0.3420000000000005; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.4980000000000002;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.5299999999999994;
            0.8079999999999998; 0.17600000000000016; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 1";
        pattern = Pavement { side = 4; tile = 6; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.5900000000000001; 0.5299999999999994;
            0.5519999999999996; 0.17600000000000016; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 3";
        pattern = Pavement { side = 4; tile = 6; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.4980000000000002;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.17600000000000016; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 4";
        pattern = Pavement { side = 4; tile = 6; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.17600000000000016; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 5";
        pattern = Pavement { side = 4; tile = 6; number = 5; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 6";
        pattern = Pavement { side = 4; tile = 6; number = 6; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.8960000000000008; 0.8900000000000001; 0.0; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.0; 0.5399999999999991;
            0.0; 0.8979999999999997; 0.5860000000000003; 0.7; 0.4980000000000002;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.0; 0.5299999999999994;
            0.8079999999999998; 0.0; 0.7959999999999994; 0.84; 0.272;
            0.0; 0.9199999999999999; 0.988; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 6 7";
        pattern = Pavement { side = 4; tile = 6; number = 7; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.0; 0.5800000000000001; 0.6619999999999999; 0.019999999999999574;
            0.12199999999999989; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.0; 0.0; 0.254;
            0.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.0; 0.8979999999999997; 0.8700000000000001; 0.7; 0.0;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.0; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 6 8";
        pattern = Pavement { side = 4; tile = 6; number = 8; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 9";
        pattern = Pavement { side = 4; tile = 6; number = 9; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.0; 0.5800000000000001; 0.6619999999999999; 0.019999999999999574;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.0; 0.0; 0.254;
            0.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.0; 0.8979999999999997; 0.5860000000000003; 0.7; 0.0;
            0.9219999999999997; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.0; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 6 10";
        pattern = Pavement { side = 4; tile = 6; number = 10; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.0; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.8940000000000001; 0.3879999999999999; 0.13000000000000078; 0.45199999999999996;
            0.8960000000000008; 0.0; 0.0; 0.0; 0.254;
            0.0; 0.6379999999999999; 0.9220000000000006; 0.0; 0.0;
            0.0; 0.8979999999999997; 0.8700000000000001; 0.7; 0.0;
            0.9219999999999997; 0.29800000000000004; 0.3520000000000003; 0.0; 0.5299999999999994;
            0.5519999999999996; 0.0; 0.7959999999999994; 0.84; 0.272;
            0.0; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 6 11";
        pattern = Pavement { side = 4; tile = 6; number = 11; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.0; 0.3999999999999999; 0.3879999999999999; 0.13000000000000078; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.0; 0.9220000000000006; 0.0; 0.8520000000000003;
            0.9039999999999999; 0.10200000000000031; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.0; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.8580000000000001; 0.0; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 12";
        pattern = Pavement { side = 4; tile = 6; number = 12; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.045999999999999375;
            0.9700000000000006; 0.6379999999999999; 0.48600000000000065; 0.758; 0.8520000000000003;
            0.6159999999999997; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.474; 0.9640000000000004; 0.42599999999999993; 0.5900000000000001; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 13";
        pattern = Pavement { side = 4; tile = 6; number = 13; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.9640000000000004; 0.42599999999999993; 0.5900000000000001; 0.5299999999999994;
            0.5519999999999996; 0.17600000000000016; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 14";
        pattern = Pavement { side = 4; tile = 6; number = 14; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.15199999999999925; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.6539999999999999; 0.4980000000000002;
            0.474; 0.9640000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.42600000000000005; 0.766;
          |];
      };
      {
        label = "pavement 4 6 15";
        pattern = Pavement { side = 4; tile = 6; number = 15; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.12199999999999989; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.0; 0.8900000000000001; 0.0; 0.0; 0.045999999999999375;
            0.9700000000000006; 0.6379999999999999; 0.48600000000000065; 0.0; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.0; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.0; 0.5299999999999994;
            0.8079999999999998; 0.0; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 16";
        pattern = Pavement { side = 4; tile = 6; number = 16; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.0; 0.6699999999999999; 0.21599999999999997;
            0.0; 0.0; 0.5720000000000001; 0.13000000000000078; 0.0;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.0;
            0.9700000000000006; 0.6379999999999999; 0.48600000000000065; 0.0; 0.8520000000000003;
            0.0; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.42599999999999993; 0.0; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.0;
          |];
      };
      {
        label = "pavement 4 6 17";
        pattern = Pavement { side = 4; tile = 6; number = 17; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.019999999999999574;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.8980000000000001; 0.045999999999999375;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 18";
        pattern = Pavement { side = 4; tile = 6; number = 18; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.019999999999999574;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.9540000000000002; 0.045999999999999375;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.4980000000000002;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.7619999999999996; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 19";
        pattern = Pavement { side = 4; tile = 6; number = 19; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.9199999999999999; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.045999999999999375;
            0.9700000000000006; 0.7539999999999996; 0.48600000000000065; 0.758; 0.8520000000000003;
            0.6159999999999997; 0.10200000000000031; 0.8700000000000001; 0.7; 0.4980000000000002;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.5900000000000001; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.7619999999999996; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 20";
        pattern = Pavement { side = 4; tile = 6; number = 20; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.19599999999999973; 0.4740000000000002;
            0.9199999999999999; 0.7380000000000004; 0.754; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.8700000000000001; 0.7; 0.4980000000000002;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.17600000000000016; 0.7959999999999994; 0.13600000000000012; 0.14800000000000002;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.42600000000000005; 0.766;
          |];
      };
      {
        label = "pavement 4 6 21";
        pattern = Pavement { side = 4; tile = 6; number = 21; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.5900000000000001; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.13600000000000012; 0.14800000000000002;
            0.8580000000000001; 0.7619999999999996; 0.988; 0.42600000000000005; 0.766;
          |];
      };
      {
        label = "pavement 4 6 22";
        pattern = Pavement { side = 4; tile = 6; number = 22; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.10200000000000031; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 23";
        pattern = Pavement { side = 4; tile = 6; number = 23; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.3680000000000003; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.10200000000000031; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.14800000000000002;
            0.8580000000000001; 0.7619999999999996; 0.988; 0.42600000000000005; 0.766;
          |];
      };
      {
        label = "pavement 4 6 24";
        pattern = Pavement { side = 4; tile = 6; number = 24; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.8980000000000001; 0.045999999999999375;
            0.6739999999999999; 0.6379999999999999; 0.48600000000000065; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 25";
        pattern = Pavement { side = 4; tile = 6; number = 25; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.8399999999999999;
            0.8079999999999998; 0.17600000000000016; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 26";
        pattern = Pavement { side = 4; tile = 6; number = 26; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.0; 0.0; 0.3879999999999999; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.7380000000000004; 0.0; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.758; 0.8520000000000003;
            0.6159999999999997; 0.10200000000000031; 0.8700000000000001; 0.6539999999999999; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.0; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.0; 0.7619999999999996; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 27";
        pattern = Pavement { side = 4; tile = 6; number = 27; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.8940000000000001; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 28";
        pattern = Pavement { side = 4; tile = 6; number = 28; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.10200000000000031; 0.5860000000000003; 0.6539999999999999; 0.4980000000000002;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 29";
        pattern = Pavement { side = 4; tile = 6; number = 29; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999; 0.9180000000000001;
            0.474; 0.29800000000000004; 0.3520000000000003; 0.9280000000000008; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 30";
        pattern = Pavement { side = 4; tile = 6; number = 30; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.019999999999999574;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.045999999999999375;
            0.9700000000000006; 0.7539999999999996; 0.48600000000000065; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.10200000000000031; 0.5860000000000003; 0.7; 0.4980000000000002;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.9280000000000008; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.7959999999999994; 0.13600000000000012; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 31";
        pattern = Pavement { side = 4; tile = 6; number = 31; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.019999999999999574;
            0.18199999999999994; 0.8940000000000001; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.8960000000000008; 0.7380000000000004; 0.15199999999999925; 0.9540000000000002; 0.045999999999999375;
            0.9700000000000006; 0.6379999999999999; 0.48600000000000065; 0.758; 0.8520000000000003;
            0.6159999999999997; 0.10200000000000031; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.8399999999999999;
            0.5519999999999996; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 32";
        pattern = Pavement { side = 4; tile = 6; number = 32; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.9700000000000006; 0.7539999999999996; 0.9220000000000006; 0.3420000000000005; 0.8520000000000003;
            0.6159999999999997; 0.10200000000000031; 0.5860000000000003; 0.7; 0.4980000000000002;
            0.474; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.84; 0.272;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 33";
        pattern = Pavement { side = 4; tile = 6; number = 33; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.09600000000000009; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.12199999999999989; 0.8940000000000001; 0.3879999999999999; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.6379999999999999; 0.48600000000000065; 0.3420000000000005; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.8700000000000001; 0.7; 0.9180000000000001;
            0.9219999999999997; 0.9640000000000004; 0.42599999999999993; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.9199999999999999; 0.988; 0.42600000000000005; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 4 6 34";
        pattern = Pavement { side = 4; tile = 6; number = 34; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.045999999999999375;
            0.9700000000000006; 0.7539999999999996; 0.48600000000000065; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.10200000000000031; 0.8700000000000001; 0.6539999999999999; 0.9180000000000001;
            0.9219999999999997; 0.29800000000000004; 0.42599999999999993; 0.5900000000000001; 0.8399999999999999;
            0.8079999999999998; 0.9819999999999993; 0.7959999999999994; 0.84; 0.272;
            0.22199999999999998; 0.7619999999999996; 0.4480000000000004; 0.6460000000000008; 0.766;
          |];
      };
      {
        label = "pavement 4 6 35";
        pattern = Pavement { side = 4; tile = 6; number = 35; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.8940000000000001; 0.5720000000000001; 0.19599999999999973; 0.4740000000000002;
            0.8960000000000008; 0.8900000000000001; 0.15199999999999925; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.8700000000000001; 0.7; 0.4980000000000002;
            0.9219999999999997; 0.9640000000000004; 0.3520000000000003; 0.9280000000000008; 0.5299999999999994;
            0.8079999999999998; 0.9819999999999993; 0.6240000000000006; 0.84; 0.14800000000000002;
            0.8580000000000001; 0.9199999999999999; 0.4480000000000004; 0.42600000000000005; 0.7620000000000005;
          |];
      };
      {
        label = "pavement 6 1 1";
        pattern = Pavement { side = 6; tile = 1; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 2 1";
        pattern = Pavement { side = 6; tile = 2; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.3336149713413855; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.7123035633621577; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 3 1";
        pattern = Pavement { side = 6; tile = 3; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 3 2";
        pattern = Pavement { side = 6; tile = 3; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.0; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.03261790553987476; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 3 3";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.3336149713413855; 0.3329589335531373;
            0.0; 0.888972745734183; 0.2793919347491379; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.08894127521877093; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 4 1";
        pattern = Pavement { side = 6; tile = 4; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 4 2";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.2793919347491379; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.0; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.0; 0.0; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 4 3";
        pattern = Pavement { side = 6; tile = 4; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 4 4";
        pattern = Pavement { side = 6; tile = 4; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 4 5";
        pattern = Pavement { side = 6; tile = 4; number = 5; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.0; 0.0;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.0; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 4 6";
        pattern = Pavement { side = 6; tile = 4; number = 6; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.3336149713413855; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.03261790553987476; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.7123035633621577; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 4 7";
        pattern = Pavement { side = 6; tile = 4; number = 7; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.3336149713413855; 0.0;
            0.0; 0.888972745734183; 0.2793919347491379; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.08894127521877093; 0.7123035633621577; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 1";
        pattern = Pavement { side = 6; tile = 5; number = 1; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 2";
        pattern = Pavement { side = 6; tile = 5; number = 2; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.0; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 3";
        pattern = Pavement { side = 6; tile = 5; number = 3; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 4";
        pattern = Pavement { side = 6; tile = 5; number = 4; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.3336149713413855; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 5 5";
        pattern = Pavement { side = 6; tile = 5; number = 5; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.0; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 6";
        pattern = Pavement { side = 6; tile = 5; number = 6; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.0; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.0; 0.7529914417620958; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 7";
        pattern = Pavement { side = 6; tile = 5; number = 7; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.0; 0.0; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 8";
        pattern = Pavement { side = 6; tile = 5; number = 8; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.0; 0.0; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.5800427185942463; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 9";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.3336149713413855; 0.0;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.7123035633621577; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.0; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 5 10";
        pattern = Pavement { side = 6; tile = 5; number = 10; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.3336149713413855; 0.3329589335531373;
            0.0; 0.888972745734183; 0.2793919347491379; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.0; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.05741235551971402; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.08894127521877093; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 11";
        pattern = Pavement { side = 6; tile = 5; number = 11; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.0; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.0; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.5800427185942463; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 12";
        pattern = Pavement { side = 6; tile = 5; number = 12; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.0; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.0;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 5 13";
        pattern = Pavement { side = 6; tile = 5; number = 13; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 5 14";
        pattern = Pavement { side = 6; tile = 5; number = 14; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.5800427185942463; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 15";
        pattern = Pavement { side = 6; tile = 5; number = 15; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.0;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.939957281405754; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 16";
        pattern = Pavement { side = 6; tile = 5; number = 16; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.0; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.0;
          |];
      };
      {
        label = "pavement 6 5 17";
        pattern = Pavement { side = 6; tile = 5; number = 17; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.5800427185942463; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 18";
        pattern = Pavement { side = 6; tile = 5; number = 18; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.0;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 19";
        pattern = Pavement { side = 6; tile = 5; number = 19; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.2793919347491379; 0.0; 0.8712770758606078;
            0.28287039040387596; 0.0; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.08894127521877093; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.5800427185942463; 0.0;
            0.0; 0.0; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 20";
        pattern = Pavement { side = 6; tile = 5; number = 20; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.0; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 21";
        pattern = Pavement { side = 6; tile = 5; number = 21; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.0; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246; 0.9798334941830443;
            0.6614706376093858; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.0; 0.02862848602143675; 0.5800427185942463; 0.0;
            0.11656608684916825; 0.3595147374217367; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 6 5 22";
        pattern = Pavement { side = 6; tile = 5; number = 22; exterior = 0; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.2793919347491379; 0.0; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246; 0.9798334941830443;
            0.08894127521877093; 0.9101517816810781; 0.0; 0.0; 0.0;
            0.0; 0.7824656085719575; 0.02862848602143675; 0.939957281405754; 0.35246649395507135;
            0.11656608684916825; 0.0; 0.0; 0.775268147526427; 0.04180236719219155;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 0.9220000000000006; 1.0; 0.5399999999999991;
            0.6159999999999997; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 0.9220000000000006; 0.8315816255786321; 0.5399999999999991;
            0.6159999999999997; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 0.9220000000000006; 1.0; 0.5399999999999991;
            0.6159999999999997; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 0.9220000000000006; 0.8315816255786321; 0.5399999999999991;
            0.6159999999999997; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 0.9220000000000006; 1.0; 0.5399999999999991;
            0.6159999999999997; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 0 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 0.9220000000000006; 0.8315816255786321; 0.5399999999999991;
            0.6159999999999997; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 1.0; 0.758; 0.5399999999999991;
            0.5199999999999996; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.5199999999999996; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.5199999999999996; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 1.0; 0.758; 0.5399999999999991;
            0.5199999999999996; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.5199999999999996; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.5199999999999996; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 1.0; 0.758; 0.5399999999999991;
            0.5199999999999996; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.5199999999999996; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 1 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 1.0;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.934000000000001; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.5199999999999996; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 1.0; 0.758; 0.5399999999999991;
            0.6041818599407043; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.6041818599407043; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.6041818599407043; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 1.0; 0.758; 0.5399999999999991;
            0.6041818599407043; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.6041818599407043; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.6041818599407043; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 1.0; 0.758; 0.5399999999999991;
            0.6041818599407043; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.6041818599407043; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 2 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.5617477389130425;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.3868366882946248; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.6041818599407043; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6159999999999997; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.6159999999999997; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.6159999999999997; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.5199999999999996; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.5199999999999996; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.5199999999999996; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 0; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.5800000000000001; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.4740000000000002;
            0.8960000000000008; 0.7380000000000004; 0.754; 0.9540000000000002; 0.254;
            0.6739999999999999; 0.7539999999999996; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.6041818599407043; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 1; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.9480000000000004; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.9260000000000002;
            0.8960000000000008; 0.7380000000000004; 0.9059999999999993; 0.9540000000000002; 0.2999999999999994;
            0.6739999999999999; 1.0; 1.0; 1.0; 0.5399999999999991;
            0.6041818599407043; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 6 2 form 3 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 6; number = 2; exterior = 2; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.686894460597842; 0.6619999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.6549656479541505;
            0.8960000000000008; 0.7380000000000004; 0.7691683820854832; 0.9540000000000002; 0.2581317493064345;
            0.6739999999999999; 0.9877044092237308; 1.0; 0.8315816255786321; 0.5399999999999991;
            0.6041818599407043; 0.9037743081101606; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.9480000000000004; 1.0; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.96; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.9059999999999993; 0.8980000000000001; 0.254;
            1.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.686894460597842; 0.9418832199375886; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.6911787033756176; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.7691683820854832; 0.8980000000000001; 0.254;
            1.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.9480000000000004; 1.0; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.96; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.9059999999999993; 0.8980000000000001; 0.254;
            1.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.686894460597842; 0.9418832199375886; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.6911787033756176; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.7691683820854832; 0.8980000000000001; 0.254;
            1.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.9480000000000004; 1.0; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.96; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.9059999999999993; 0.8980000000000001; 0.254;
            1.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 0 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.686894460597842; 0.9418832199375886; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.6911787033756176; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.7691683820854832; 0.8980000000000001; 0.254;
            1.0; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.5800000000000001; 0.6699999999999999; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.5720000000000001; 0.934000000000001; 0.9779999999999998;
            0.9199999999999999; 1.0; 0.754; 0.944; 1.0;
            0.9700000000000006; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.9480000000000004; 1.0; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.96; 0.934000000000001; 0.9779999999999998;
            1.0; 1.0; 0.9059999999999993; 0.944; 1.0;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.686894460597842; 0.9418832199375886; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.6911787033756176; 0.934000000000001; 0.9779999999999998;
            1.0; 1.0; 0.7691683820854832; 0.944; 1.0;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.5800000000000001; 0.6699999999999999; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.5720000000000001; 0.934000000000001; 0.9779999999999998;
            0.9199999999999999; 1.0; 0.754; 0.944; 1.0;
            0.9700000000000006; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.9480000000000004; 1.0; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.96; 0.934000000000001; 0.9779999999999998;
            1.0; 1.0; 0.9059999999999993; 0.944; 1.0;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.686894460597842; 0.9418832199375886; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.6911787033756176; 0.934000000000001; 0.9779999999999998;
            1.0; 1.0; 0.7691683820854832; 0.944; 1.0;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.5800000000000001; 0.6699999999999999; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.5720000000000001; 0.934000000000001; 0.9779999999999998;
            0.9199999999999999; 1.0; 0.754; 0.944; 1.0;
            0.9700000000000006; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.9480000000000004; 1.0; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.96; 0.934000000000001; 0.9779999999999998;
            1.0; 1.0; 0.9059999999999993; 0.944; 1.0;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 1 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            1.0; 0.1280000000000001; 0.686894460597842; 0.9418832199375886; 1.0;
            0.18199999999999994; 0.5059999999999998; 0.6911787033756176; 0.934000000000001; 0.9779999999999998;
            1.0; 1.0; 0.7691683820854832; 0.944; 1.0;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.5800000000000001; 0.6699999999999999; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.5720000000000001; 0.3868366882946248; 0.5443380458953926;
            0.9199999999999999; 0.9080733738512259; 0.754; 0.8985573470401151; 0.6329825473654025;
            0.9700000000000006; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.9480000000000004; 1.0; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.96; 0.3868366882946248; 0.5443380458953926;
            1.0; 0.9080733738512259; 0.9059999999999993; 0.8985573470401151; 0.6329825473654025;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.686894460597842; 0.9418832199375886; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.6911787033756176; 0.3868366882946248; 0.5443380458953926;
            1.0; 0.9080733738512259; 0.7691683820854832; 0.8985573470401151; 0.6329825473654025;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.5800000000000001; 0.6699999999999999; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.5720000000000001; 0.3868366882946248; 0.5443380458953926;
            0.9199999999999999; 0.9080733738512259; 0.754; 0.8985573470401151; 0.6329825473654025;
            0.9700000000000006; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.9480000000000004; 1.0; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.96; 0.3868366882946248; 0.5443380458953926;
            1.0; 0.9080733738512259; 0.9059999999999993; 0.8985573470401151; 0.6329825473654025;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.686894460597842; 0.9418832199375886; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.6911787033756176; 0.3868366882946248; 0.5443380458953926;
            1.0; 0.9080733738512259; 0.7691683820854832; 0.8985573470401151; 0.6329825473654025;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.5800000000000001; 0.6699999999999999; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.5720000000000001; 0.3868366882946248; 0.5443380458953926;
            0.9199999999999999; 0.9080733738512259; 0.754; 0.8985573470401151; 0.6329825473654025;
            0.9700000000000006; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.9480000000000004; 1.0; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.96; 0.3868366882946248; 0.5443380458953926;
            1.0; 0.9080733738512259; 0.9059999999999993; 0.8985573470401151; 0.6329825473654025;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 2 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6968535587963975; 0.17885445869809402; 0.686894460597842; 0.9418832199375886; 0.5617477389130425;
            0.18199999999999994; 0.40400712248905624; 0.6911787033756176; 0.3868366882946248; 0.5443380458953926;
            1.0; 0.9080733738512259; 0.7691683820854832; 0.8985573470401151; 0.6329825473654025;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 1.0; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.3420000000000005; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.9480000000000004; 1.0; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.96; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.9059999999999993; 0.8980000000000001; 0.2999999999999994;
            1.0; 0.6379999999999999; 1.0; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.29800000000000004; 0.686894460597842; 0.9418832199375886; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.6911787033756176; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.7691683820854832; 0.8980000000000001; 0.2581317493064345;
            1.0; 0.6379999999999999; 1.0; 0.3420000000000005; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.0; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.10000000000000053; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.0; 0.9480000000000004; 1.0; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.96; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.9059999999999993; 0.8980000000000001; 0.2999999999999994;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.0; 0.686894460597842; 0.9418832199375886; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.6911787033756176; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.7691683820854832; 0.8980000000000001; 0.2581317493064345;
            1.0; 0.6379999999999999; 1.0; 0.10000000000000053; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 0; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.17885445869809402; 0.5800000000000001; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.5720000000000001; 0.13000000000000078; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.29890942097329587; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.7;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 1; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.17885445869809402; 0.9480000000000004; 1.0; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.96; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.9059999999999993; 0.8980000000000001; 0.2999999999999994;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 1.0;
          |];
      };
      {
        label = "pavement 4 4 5 form 3 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 4; number = 5; exterior = 2; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.17885445869809402; 0.686894460597842; 0.9418832199375886; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.6911787033756176; 0.13000000000000078; 0.45199999999999996;
            1.0; 0.8900000000000001; 0.7691683820854832; 0.8980000000000001; 0.2581317493064345;
            1.0; 0.6379999999999999; 1.0; 0.29890942097329587; 0.5399999999999991;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.9579749474803606;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 0 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            0.9199999999999999; 0.8900000000000001; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            1.0; 1.0; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            1.0; 1.0; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            0.9199999999999999; 0.8900000000000001; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            1.0; 1.0; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            1.0; 1.0; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            0.9199999999999999; 0.8900000000000001; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            1.0; 1.0; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 1 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.0519999999999996; 1.0; 1.0;
            1.0; 0.29400000000000004; 0.8159999999999998; 1.0; 0.07399999999999984;
            1.0; 1.0; 1.0; 0.8520000000000003; 1.0;
            1.0; 0.6379999999999999; 1.0; 1.0; 0.39199999999999946;
            1.0; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            0.9199999999999999; 0.8900000000000001; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            1.0; 1.0; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            1.0; 1.0; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            0.9199999999999999; 0.8900000000000001; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            1.0; 1.0; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            1.0; 1.0; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            0.9199999999999999; 0.8900000000000001; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            1.0; 1.0; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 2 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.241169320599121; 1.0; 0.5871534267360541;
            0.6297263573986891; 0.3907086082997725; 0.4524902753547093; 0.6453923544249258; 0.24040800425491593;
            1.0; 1.0; 0.9482350987496353; 0.8881071941544053; 0.5756370140359108;
            0.9967914262636453; 0.6379999999999999; 0.9895426610153404; 0.8771062836184849; 0.5167774839683061;
            0.9423367370257918; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 0 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.3680000000000003; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3999999999999999; 0.3879999999999999; 0.19599999999999973; 0.45199999999999996;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 0 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.3680000000000003; 1.0; 0.23599999999999954;
            0.3039999999999998; 0.3999999999999999; 0.3879999999999999; 0.3260000000000005; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 0 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 0; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.3680000000000003; 0.9418832199375886; 0.21692394980729993;
            0.21910727965998747; 0.3999999999999999; 0.3879999999999999; 0.23519353732617762; 0.45199999999999996;
            1.0; 1.0; 0.754; 0.8980000000000001; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5399999999999991;
            0.9039999999999999; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 1 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.0; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.29400000000000004; 0.3879999999999999; 0.19599999999999973; 0.0;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8520000000000003; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.39199999999999946;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 1 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.0; 1.0; 0.23599999999999954;
            0.3039999999999998; 0.29400000000000004; 0.3879999999999999; 0.3260000000000005; 0.0;
            1.0; 1.0; 0.754; 0.8520000000000003; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.39199999999999946;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 1 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 1; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.0; 0.9418832199375886; 0.21692394980729993;
            0.21910727965998747; 0.29400000000000004; 0.3879999999999999; 0.23519353732617762; 0.0;
            1.0; 1.0; 0.754; 0.8520000000000003; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.39199999999999946;
            0.9039999999999999; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 2 exterior 0";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 0; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.5739999999999998; 0.241169320599121; 0.6699999999999999; 0.21599999999999997;
            0.18199999999999994; 0.3907086082997725; 0.3879999999999999; 0.19599999999999973; 0.24040800425491593;
            0.9199999999999999; 0.8900000000000001; 0.754; 0.8881071941544053; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5167774839683061;
            0.9039999999999999; 0.8979999999999997; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 2 exterior 1";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 1; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.8719999999999999; 0.241169320599121; 1.0; 0.23599999999999954;
            0.3039999999999998; 0.3907086082997725; 0.3879999999999999; 0.3260000000000005; 0.24040800425491593;
            1.0; 1.0; 0.754; 0.8881071941544053; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5167774839683061;
            0.9039999999999999; 1.0; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 4 5 7 form 3 interior 2 exterior 2";
        pattern = Pavement { side = 4; tile = 5; number = 7; exterior = 2; interior = 2; form = 3 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.43599999999999994; 0.6467456996378096; 0.241169320599121; 0.9418832199375886; 0.21692394980729993;
            0.21910727965998747; 0.3907086082997725; 0.3879999999999999; 0.23519353732617762; 0.24040800425491593;
            1.0; 1.0; 0.754; 0.8881071941544053; 0.254;
            0.9700000000000006; 0.6379999999999999; 0.9220000000000006; 0.758; 0.5167774839683061;
            0.9039999999999999; 0.9037743081101606; 0.5860000000000003; 0.6539999999999999;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 0 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 1 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.43199999999999994;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.20399999999999974; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 1; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 12 form 2 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 12; exterior = 2; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.339257314656553;
            0.0; 1.0; 0.8057941448029203; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 0 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.5478665176788411; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.3247641889202504; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 1 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.9037330353576816; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.001249821594790479; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.4547641889202503; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.05741235551971402; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.22105926663978526; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 0.9175109372919816; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 1; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.5913971886922791; 0.3111451730915491; 1.0; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 6 4 form 2 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 6; number = 4; exterior = 2; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.6213635244131055; 0.0; 0.2725386608210716; 0.6572299426827712; 0.374551798769727;
            0.0; 0.888972745734183; 0.5566080652508625; 0.0; 0.0;
            0.0; 0.1342537669151096; 0.7910085582379066; 0.0; 0.07705495122319239;
            0.0; 0.6159464572127321; 0.3111451730915491; 1.0; 0.0;
            0.17109131947773004; 0.18686863908949536; 0.33564306649925185; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.6882693304105361; 0.6572299426827712; 0.3329589335531373;
            0.0; 1.0; 1.0; 0.2669287716605492; 0.0;
            0.0; 0.19574623308489017; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.357382094460125; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 0; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.693216648416744; 0.6572299426827712; 0.374551798769727;
            0.0; 1.0; 1.0; 0.2669287716605492; 0.0;
            0.0; 0.2002032052581615; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.059384953972628676; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.39518575177380566; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.4157306695894648; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.2669287716605492; 0.0;
            0.0; 0.1342537669151096; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.3247641889202504; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.6882693304105361; 0.6572299426827712; 0.3329589335531373;
            0.0; 1.0; 1.0; 0.2669287716605492; 0.0;
            0.0; 0.19574623308489017; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.357382094460125; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.693216648416744; 0.6572299426827712; 0.374551798769727;
            0.0; 1.0; 1.0; 0.2669287716605492; 0.0;
            0.0; 0.2002032052581615; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.059384953972628676; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.39518575177380566; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.4157306695894648; 0.6572299426827712; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.2669287716605492; 0.0;
            0.0; 0.1342537669151096; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.3247641889202504; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.6882693304105361; 0.6572299426827712; 0.3329589335531373;
            0.0; 1.0; 1.0; 0.2669287716605492; 0.0;
            0.0; 0.19574623308489017; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.05937508920260359; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.357382094460125; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 0 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.25986651767884084; 0.0; 0.693216648416744; 0.6572299426827712; 0.374551798769727;
            0.0; 1.0; 1.0; 0.2669287716605492; 0.0;
            0.0; 0.2002032052581615; 0.961982883524189; 0.4562240477140772; 0.07705495122319239;
            0.059384953972628676; 0.0; 0.9197096538169002; 0.19151093729198176; 0.48388235210354325;
            0.6727061777598571; 0.18686863908949536; 0.39518575177380566; 0.18532011140769555;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.4157306695894648; 1.0; 0.3329589335531373;
            0.0029191757290967235; 0.8965136271329087; 0.7227838694982753; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.1342537669151096; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.05937508920260359; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.3247641889202504; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.6882693304105361; 1.0; 0.3329589335531373;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.19574623308489017; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.05937508920260359; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.357382094460125; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.693216648416744; 1.0; 0.374551798769727;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.2002032052581615; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.059384953972628676; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.39518575177380566; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.4157306695894648; 1.0; 0.3329589335531373;
            0.0029191757290967235; 0.8965136271329087; 0.7227838694982753; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.1342537669151096; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.05937508920260359; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.3247641889202504; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.6882693304105361; 1.0; 0.3329589335531373;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.19574623308489017; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.05937508920260359; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.357382094460125; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.693216648416744; 1.0; 0.374551798769727;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.2002032052581615; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.059384953972628676; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.39518575177380566; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.4157306695894648; 1.0; 0.3329589335531373;
            0.0029191757290967235; 0.8965136271329087; 0.7227838694982753; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.1342537669151096; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.05937508920260359; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.3247641889202504; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.6882693304105361; 1.0; 0.3329589335531373;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.19574623308489017; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.05937508920260359; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.357382094460125; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 1 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.7117330353576814; 0.11934556833556798; 0.693216648416744; 1.0; 0.374551798769727;
            0.0029191757290967235; 1.0; 1.0; 0.2738575433210966; 0.3614458482787837;
            0.14974078080775488; 0.2002032052581615; 1.0; 0.5582240477140772; 0.2461099024463831;
            0.059384953972628676; 0.19879437738455596; 1.0; 0.8670218745839628; 0.6717647042070869;
            1.0; 0.5777372781789909; 0.39518575177380566; 0.4853201114076957;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.4157306695894648; 0.8995811711848803; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.1342537669151096; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.05937508920260359; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.3247641889202504; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 0 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.6882693304105361; 0.8995811711848803; 0.3329589335531373;
            0.0; 1.0; 1.0; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.19574623308489017; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.05937508920260359; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.357382094460125; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 0 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.693216648416744; 0.8995811711848803; 0.374551798769727;
            0.0; 1.0; 1.0; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.2002032052581615; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.059384953972628676; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.39518575177380566; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.4157306695894648; 0.8995811711848803; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.1342537669151096; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.05937508920260359; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.3247641889202504; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 1 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.6882693304105361; 0.8995811711848803; 0.3329589335531373;
            0.0; 1.0; 1.0; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.19574623308489017; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.05937508920260359; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.357382094460125; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 1 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.693216648416744; 0.8995811711848803; 0.374551798769727;
            0.0; 1.0; 1.0; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.2002032052581615; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.059384953972628676; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.39518575177380566; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.4157306695894648; 0.8995811711848803; 0.3329589335531373;
            0.0; 0.8965136271329087; 0.7227838694982753; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.1342537669151096; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.05937508920260359; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.3247641889202504; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 2 exterior 1";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 1; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.6882693304105361; 0.8995811711848803; 0.3329589335531373;
            0.0; 1.0; 1.0; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.19574623308489017; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.05937508920260359; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.357382094460125; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 3 2 1 form 2 interior 2 exterior 2";
        pattern = Pavement { side = 3; tile = 2; number = 1; exterior = 2; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.39155738528756573; 0.0; 0.693216648416744; 0.8995811711848803; 0.374551798769727;
            0.0; 1.0; 1.0; 0.26696053768312833; 0.049119191741618495;
            0.0; 0.2002032052581615; 1.0; 0.46256950613965914; 0.09759290616649549;
            0.059384953972628676; 0.0; 1.0; 0.4842836527807475; 0.5051089544742978;
            0.7993916483131078; 0.289263926178929; 0.39518575177380566; 0.24624664481061423;
          |];
      };
      {
        label = "pavement 6 4 2 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.41800000000000015; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.06149246616978088; 0.7720000000000011; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.4157306695894648; 0.6763850286586144; 0.0;
            0.0; 0.888972745734183; 0.37042825090561615; 0.2669287716605492; 0.0;
            0.28287039040387596; 0.06149246616978088; 0.769635124511459; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.0;
            0.0029191757290967235; 1.0; 0.2793919347491379; 0.2738575433210966; 0.0;
            0.3577407808077533; 0.17149246616978076; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.0;
            0.0029191757290967235; 1.0; 0.41800000000000015; 0.2738575433210966; 0.0;
            0.3577407808077533; 0.17149246616978076; 0.7720000000000011; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.7153455683355681; 0.7360000000000007; 1.0; 0.0;
            0.0029191757290967235; 1.0; 0.37042825090561615; 0.2738575433210966; 0.0;
            0.3577407808077533; 0.17149246616978076; 0.769635124511459; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.0;
            0.0; 1.0; 0.2793919347491379; 0.26696053768312833; 0.0;
            0.28655066540420915; 0.07027804607853681; 0.7529914417620958; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.0;
            0.0; 1.0; 0.41800000000000015; 0.26696053768312833; 0.0;
            0.28655066540420915; 0.07027804607853681; 0.7720000000000011; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 4 2 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 4; number = 2; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6576832881441074; 0.47860283224239125; 0.9127635180689242; 0.0;
            0.0; 1.0; 0.37042825090561615; 0.26696053768312833; 0.0;
            0.28655066540420915; 0.07027804607853681; 0.769635124511459; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.0; 0.0;
          |];
      };
      {
        label = "pavement 6 5 9 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.49542245701207843; 0.0;
            0.0; 0.8372295593006374; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 6 5 9 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.4228141684475073; 0.0;
            0.0; 0.8141874912920157; 0.5566080652508625; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.03261790553987476; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 6 5 9 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.3336149713413855; 0.0;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 0.7910085582379066; 0.0; 0.0;
            0.05999999999999872; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 6 5 9 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.49542245701207843; 0.0;
            0.0; 0.8372295593006374; 0.5566080652508625; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 0.7910085582379066; 0.0; 0.0;
            0.05999999999999872; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 6 5 9 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.4228141684475073; 0.0;
            0.0; 0.8141874912920157; 0.5566080652508625; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 0.7910085582379066; 0.0; 0.0;
            0.05999999999999872; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.2599999999999998; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 6 5 9 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.3336149713413855; 0.0;
            0.0; 0.7854863728670917; 0.5566080652508625; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 0.7910085582379066; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 6 5 9 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.49542245701207843; 0.0;
            0.0; 0.8372295593006374; 0.5566080652508625; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 0.7910085582379066; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 6 5 9 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 5; number = 9; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.6556727841677841; 0.0; 0.4228141684475073; 0.0;
            0.0; 0.8141874912920157; 0.5566080652508625; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 0.7910085582379066; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.07042106842171779; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 6 3 3 form 0 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 1; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.49542245701207843; 0.3329589335531373;
            0.0; 0.888972745734183; 0.41800000000000015; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 6 3 3 form 0 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 2; form = 0 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.4157306695894648; 0.4228141684475073; 0.3329589335531373;
            0.0; 0.888972745734183; 0.37042825090561615; 0.2669287716605492; 0.8712770758606078;
            0.28287039040387596; 0.06149246616978088; 0.7910085582379066; 0.0; 0.0;
            0.05937508920260359; 0.0; 0.0; 0.0; 0.0;
            0.38470617775985694; 0.0; 0.0; 0.35733994429615246;
          |];
      };
      {
        label = "pavement 6 3 3 form 1 interior 0 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 0; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.7360000000000007; 0.3336149713413855; 0.43199999999999994;
            0.0; 0.888972745734183; 0.2793919347491379; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.0; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.0; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 6 3 3 form 1 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 1; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.7360000000000007; 0.49542245701207843; 0.43199999999999994;
            0.0; 0.888972745734183; 0.41800000000000015; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.0; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.0; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 6 3 3 form 1 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 2; form = 1 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.7360000000000007; 0.4228141684475073; 0.43199999999999994;
            0.0; 0.888972745734183; 0.37042825090561615; 0.2738575433210966; 1.0;
            0.3577407808077533; 0.17149246616978076; 1.0; 0.0; 0.0;
            0.05999999999999872; 0.19879437738455596; 0.0; 0.0; 0.0;
            0.9614123555197134; 0.0; 0.0; 0.6000000000000001;
          |];
      };
      {
        label = "pavement 6 3 3 form 2 interior 0 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 0; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.47860283224239125; 0.3336149713413855; 0.339257314656553;
            0.0; 0.888972745734183; 0.2793919347491379; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.0; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 6 3 3 form 2 interior 1 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 1; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.47860283224239125; 0.49542245701207843; 0.339257314656553;
            0.0; 0.888972745734183; 0.41800000000000015; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.0; 0.3945152580171148;
          |];
      };
      {
        label = "pavement 6 3 3 form 2 interior 2 exterior 0";
        pattern = Pavement { side = 6; tile = 3; number = 3; exterior = 0; interior = 2; form = 2 };
        warps = [];
        gen = 2;
        route = Exact;
        points = xz24;
        values =
          [|
            0.0; 0.0; 0.47860283224239125; 0.4228141684475073; 0.339257314656553;
            0.0; 0.888972745734183; 0.37042825090561615; 0.26696053768312833; 0.8882891774008919;
            0.28655066540420915; 0.07027804607853681; 1.0; 0.0; 0.0;
            0.05937537364336394; 0.0; 0.0; 0.0; 0.0;
            0.585458102666755; 0.0; 0.0; 0.3945152580171148;
          |];
      };
    ]

let noise : case list =
  Scene.
    [
      {
        label = "bozo, generator 1";
        pattern = Bozo;
        warps = [];
        gen = 1;
        route = Raw;
        points = g3;
        values =
          [|
            0.3855163633813812; 0.022870638565918866; 0.4609650806680474; 0.1403167894627096; 0.5536232770844886;
            0.0; 0.6215460282490619; 0.13921748864463723;
          |];
      };
      {
        label = "bozo, generator 2";
        pattern = Bozo;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.4594535863920044; 0.28180946749303176; 0.49641257966641245; 0.3393411480464229; 0.5418017364517093;
            0.23038707563518715; 0.5750740914200874; 0.3388026491427594;
          |];
      };
      {
        label = "bozo, generator 3";
        pattern = Bozo;
        warps = [];
        gen = 3;
        route = Raw;
        points = g3;
        values =
          [|
            0.5899825428730313; 0.42614644515030886; 0.6670698991837497; 0.6373813455889592; 0.6361852283192991;
            0.473164783330388; 0.6075083499016378; 0.38778689255911386;
          |];
      };
      {
        label = "spotted";
        pattern = Spotted;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.4594535863920044; 0.28180946749303176; 0.49641257966641245; 0.3393411480464229; 0.5418017364517093;
            0.23038707563518715; 0.5750740914200874; 0.3388026491427594;
          |];
      };
      {
        label = "bumps";
        pattern = Bumps;
        warps = [];
        gen = 3;
        route = Raw;
        points = g3;
        values =
          [|
            0.5899825428730313; 0.42614644515030886; 0.6670698991837497; 0.6373813455889592; 0.6361852283192991;
            0.473164783330388; 0.6075083499016378; 0.38778689255911386;
          |];
      };
      {
        label = "granite, generator 1";
        pattern = Granite;
        warps = [];
        gen = 1;
        route = Raw;
        points = g3;
        values =
          [|
            0.2035482847315989; 0.62323712683984; 0.19691651242015573; 0.4006077391754504; 0.9351483354207506;
            0.22538722773223005; 0.25505106944763184; 0.5842261974905665;
          |];
      };
      {
        label = "wrinkles, generator 1";
        pattern = Wrinkles;
        warps = [];
        gen = 1;
        route = Raw;
        points = g3;
        values =
          [|
            0.38186073252727776; 0.3550686783912019; 0.46716774211495743; 0.43498652016401035; 0.41245084564475665;
            0.1250316631827847; 0.6108490169481019; 0.28303945689496934;
          |];
      };
      {
        label = "granite, generator 2";
        pattern = Granite;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.23534114242375653; 0.6542822172575223; 0.17835821612210617; 0.43228609923554756; 0.9017404544873717;
            0.24702822028402127; 0.24113859160981824; 0.5189748676593218;
          |];
      };
      {
        label = "wrinkles, generator 2";
        pattern = Wrinkles;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.41528546229391067; 0.38903697499728696; 0.4987812397789723; 0.4673334148257857; 0.4433516272789823;
            0.13510971175781877; 0.6396279499646227; 0.3184691082772898;
          |];
      };
      {
        label = "granite, generator 3";
        pattern = Granite;
        warps = [];
        gen = 3;
        route = Raw;
        points = g3;
        values =
          [|
            0.4521991025513352; 0.36247530559702484; 0.5549590523613046; 0.31990603794068695; 0.32143443714673015;
            0.2801327072868926; 0.43513078689883544; 0.27213574644742;
          |];
      };
      {
        label = "wrinkles, generator 3";
        pattern = Wrinkles;
        warps = [];
        gen = 3;
        route = Raw;
        points = g3;
        values =
          [|
            0.7499920422222799; 0.3101381273337485; 0.731486353966869; 0.6484471006857436; 0.6939544850529539;
            0.4987799311339387; 0.5400299942847472; 0.25160728476545524;
          |];
      };
      {
        label = "dents";
        pattern = Dents;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.09698954850210965; 0.02238034298386098; 0.12232869295817443; 0.03907595262411579; 0.15904542382872094;
            0.012228532342306468; 0.19018287389715985; 0.03889021932818486;
          |];
      };
      {
        label = "cells";
        pattern = Cells;
        warps = [];
        gen = 2;
        route = Raw;
        points = g3_cells;
        values =
          [|
            0.9927426148205996; 0.8002804731950164; 0.5261024662759155; 0.08707721531391144; 0.04505110951140523;
            0.8242417054716498; 0.3355513676069677; 0.39085475145839155; 0.7573719171341509;
          |];
      };
      {
        label = "agate";
        pattern = Agate 1.;
        warps = [ Classic_turb { turbulence = v 0.0 0.0 0.0; octaves = 6; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.38705419334682106; 0.8868043949309631; 0.23050126124184253; 0.7642968507639231; 0.8937819780723072;
            0.7876126663138888; 0.1083047682598042; 0.41380987225173055;
          |];
      };
      {
        label = "agate, agate_turb 0.6, octaves 4, omega 0.6, lambda 2.5";
        pattern = Agate (f32 0.6);
        warps = [ Classic_turb { turbulence = v 0.0 0.0 0.0; octaves = 4; omega = f32 0.6; lambda = f32 2.5 } ];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.06187332838067727; 0.9020983655349494; 0.8590516080787248; 0.20127541501086074; 0.31461503103457145;
            0.7639008131387792; 0.8053694209934139; 0.07326532645704009;
          |];
      };
      {
        label = "agate, turbulence 0.4 (warped), generator 3";
        pattern = Agate 1.;
        warps = [ Classic_turb { turbulence = v 0.4 0.4 0.4; octaves = 6; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 3;
        route = Raw;
        points = g3;
        values =
          [|
            0.9888287118899839; 0.9946828741765495; 0.052013228230637386; 0.19496877021767195; 0.22699165164406226;
            0.2835402282979263; 0.9368529444608688; 0.9562500318222233;
          |];
      };
      {
        label = "marble, turbulence 0.5";
        pattern = Marble;
        warps = [ Classic_turb { turbulence = v 0.5 0.5 0.5; octaves = 6; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            0.7082849147456287; 0.18042305678256065; 3.0946192136600326; 0.012557382474421841; 5.564197777662029;
            0.1970372142705379; 0.929184045076783; 1.323724344935608;
          |];
      };
      {
        label = "marble, turbulence <0.8,0,0>, octaves 3, generator 1";
        pattern = Marble;
        warps = [ Classic_turb { turbulence = v 0.8 0.0 0.0; octaves = 3; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 1;
        route = Raw;
        points = g3;
        values =
          [|
            0.8186988659535723; 0.2516096344787191; 3.2391729563421254; 0.13877084168059467; 5.621273520383728;
            0.17728914307697227; 0.14924968614714906; 1.3899093920414116;
          |];
      };
      {
        label = "wood, turbulence <0.3,0.2,0.1>";
        pattern = Wood;
        warps = [ Classic_turb { turbulence = v 0.3 0.2 0.1; octaves = 6; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            1.1432628522504484; 2.226079082061531; 2.3979755685117796; 2.349084808517506; 5.824311767988432;
            1.2349303902433506; 5.38255547962461; 1.965973559003204;
          |];
      };
      {
        label = "spiral1 4, turbulence 0.3 (warped)";
        pattern = Spiral1 4;
        warps = [ Classic_turb { turbulence = v 0.3 0.3 0.3; octaves = 6; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            4.098645560828401; 4.828735398386096; 0.5471464523295192; 5.431726902961066; 7.8969015801111215;
            2.5916591005774854; 11.310403581388567; 0.7142269625598541;
          |];
      };
      {
        label = "spiral2 2, turbulence <0.2,0.5,0.1> (warped)";
        pattern = Spiral2 2;
        warps = [ Classic_turb { turbulence = v 0.2 0.5 0.1; octaves = 6; omega = f32 0.5; lambda = f32 2.0 } ];
        gen = 2;
        route = Raw;
        points = g3;
        values =
          [|
            1.3899355878897641; 1.658316765655496; 0.7837028338796599; 1.242111275482559; 1.385018534953863;
            1.3553706352339878; 0.7189985042314717; 0.6281056963410176;
          |];
      };
      {
        label = "waves";
        pattern = Waves 10;
        warps = [];
        gen = 2;
        route = Wrapped (f32 1.0, f32 0.0);
        points = g3;
        values =
          [|
            0.5141273724583113; 0.6642239711390072; 0.35101560842038015; 0.6460618628371335; 0.47104118338394374;
            0.6029532466562694; 0.5352551441044385; 0.6226387163144813;
          |];
      };
      {
        label = "ripples";
        pattern = Ripples 10;
        warps = [];
        gen = 2;
        route = Wrapped (f32 1.0, f32 0.0);
        points = g3;
        values =
          [|
            0.4713807133627291; 0.4305910078957192; 0.46574060512943594; 0.5799295332024895; 0.5001178137494885;
            0.4314317477914285; 0.5439110619045261; 0.29784966212081476;
          |];
      };
      {
        label = "waves, frequency 2.5, phase 0.3";
        pattern = Waves 10;
        warps = [];
        gen = 2;
        route = Wrapped (f32 2.5, f32 0.3);
        points = g3;
        values =
          [|
            0.5745079133035289; 0.8551944442350743; 0.5681336435536664; 0.6204510585719138; 0.30531163170442177;
            0.38212104884121856; 0.8613893467971099; 0.31941910109342575;
          |];
      };
      {
        label = "ripples, frequency 0.7, phase -0.45";
        pattern = Ripples 10;
        warps = [];
        gen = 2;
        route = Wrapped (f32 0.7, f32 (-0.45));
        points = g3;
        values =
          [|
            0.10446610974930393; 0.8547287654807456; 0.008155224019403662; 0.8765066997516964; 0.8121733365498305;
            0.21913581917353564; 0.89599733019321; 0.7505677483347887;
          |];
      };
      {
        label = "crackle";
        pattern = Crackle { form = v (-1.0) 1.0 0.0; metric = 2.0; offset = 0.0; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            0.05774305425914772; 0.13740258738053768; 0.1301797421049708; 0.6298808429693719; 0.5333223950166859;
            0.16854235758085312; 0.04071407959349349; 0.023516781098605555; 0.012976363360584386; 0.5720310582155586;
            0.10246691867995728; 0.22879352497384176;
          |];
      };
      {
        label = "crackle form <1,0,0>";
        pattern = Crackle { form = v 1.0 0.0 0.0; metric = 2.0; offset = 0.0; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            0.8278921659174103; 0.49849141592721236; 0.4907424703836531; 0.22586008613792352; 0.22369430622937603;
            0.6727554997279868; 0.637528589903781; 0.8225205755908054; 0.7483193350694229; 0.3839820939429862;
            0.5305669135864344; 0.5425778835813312;
          |];
      };
      {
        label = "crackle form <0,0,1>";
        pattern = Crackle { form = v 0.0 0.0 1.0; metric = 2.0; offset = 0.0; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            1.0; 0.8234394370415759; 0.7590967173621894; 0.958170207461714; 0.9221653799699853;
            0.9287087015735658; 0.8356297888525231; 0.8596743266812632; 0.8513615188395457; 1.0;
            0.7034833967518505; 0.8737102805687937;
          |];
      };
      {
        label = "crackle form <0.8,-0.3,0.6> offset 0.2";
        pattern = Crackle { form = v 0.8 (-0.3) 0.6; metric = 2.0; offset = 0.2; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            1.0; 0.7381394781106558; 0.6992455756174916; 0.5649985411709795; 0.5713175556617819;
            0.8720604981026157; 0.8379344586471345; 0.9459622815381663; 0.9082521314312484; 0.6779875222823658;
            0.6932623218060379; 0.7613343163637525;
          |];
      };
      {
        label = "crackle metric 1";
        pattern = Crackle { form = v (-1.0) 1.0 0.0; metric = 1.0; offset = 0.0; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            0.10748325693421079; 0.394827608810738; 0.2094690483994781; 1.0; 0.8441998240165419;
            0.09965312903746959; 0.08144660443067586; 0.08150188275612891; 0.09955147258006036; 0.7134299855679274;
            0.39847222798694404; 0.37447406412101714;
          |];
      };
      {
        label = "crackle metric 1 form <1,0,0> offset 0.1";
        pattern = Crackle { form = v 1.0 0.0 0.0; metric = 1.0; offset = 0.1; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            1.0; 0.7613646787125616; 0.7984660336282104; 0.47468421673402206; 0.46076237392611774;
            1.0; 0.9845026297960427; 1.0; 1.0; 0.7434763120487332;
            0.7585026478299077; 0.9443540203850688;
          |];
      };
      {
        label = "crackle metric 3 form <1,-0.5,0.25>";
        pattern = Crackle { form = v 1.0 (-0.5) 0.25; metric = 3.0; offset = 0.0; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            0.5941921290170744; 0.39097152600561624; 0.3478556320440537; 0.05183480684413705; 0.07065654742520214;
            0.4090808761783028; 0.46842704577236494; 0.539733211685494; 0.4896771577952076; 0.11520917252163179;
            0.41389987874135215; 0.3585980627677853;
          |];
      };
      {
        label = "crackle metric 0.7 offset 0.3";
        pattern = Crackle { form = v (-1.0) 1.0 0.0; metric = 0.7; offset = 0.3; solid = false };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            0.12232267906392646; 0.8725177670928554; 0.3692096647835581; 1.0; 1.0;
            0.03125664335841183; 0.11679984681986855; 0.2945356908139356; 0.004578462276024986; 0.9075567839731999;
            0.7717411697915479; 0.4715195191366144;
          |];
      };
      {
        label = "crackle solid";
        pattern = Crackle { form = v (-1.0) 1.0 0.0; metric = 2.0; offset = 0.0; solid = true };
        warps = [];
        gen = 2;
        route = Raw;
        points = crackle;
        values =
          [|
            0.5415064084258953; 0.4705533907939801; 0.6679253174513143; 0.2981155363201941; 0.5102361995193742;
            0.5697509929032187; 0.4699405841904722; 0.35746319650513836; 0.36849015768879; 0.6088182306422557;
            0.3309501394261249; 0.26050811905384913;
          |];
      };
      {
        label = "crackle solid metric 1, generator 1";
        pattern = Crackle { form = v (-1.0) 1.0 0.0; metric = 1.0; offset = 0.0; solid = true };
        warps = [];
        gen = 1;
        route = Raw;
        points = crackle;
        values =
          [|
            0.5530203894311092; 0.40817569281830757; 0.8110940998249534; 0.05615812472289128; 0.4891848532798369;
            0.6106793644277182; 0.4069246989983139; 0.22452044605953442; 0.6968752688546603; 0.6904318878111029;
            0.12318724179233981; 0.0;
          |];
      };
      {
        label = "crackle solid metric 2.5, generator 3";
        pattern = Crackle { form = v (-1.0) 1.0 0.0; metric = 2.5; offset = 0.0; solid = true };
        warps = [];
        gen = 3;
        route = Raw;
        points = crackle;
        values =
          [|
            0.5054542612622956; 0.4813138223216017; 0.4928084305295777; 0.5199374842516843; 0.6684842755676843;
            0.7169301055398482; 0.5693645853689538; 0.5698343718941898; 0.5450670787578442; 0.4541726406851816;
            0.43219698963688863; 0.5372076739143333;
          |];
      };
    ]

