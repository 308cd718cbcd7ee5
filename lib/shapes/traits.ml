(* What a kind of shape is; each shape's module writes its own. *)

type sturm = No_sturm | Sturm_flag | Sturm_bool | Sturm_float

type t = {
  name : string;
  costly : bool;
  box_test_free : bool;
  inverse_flag : bool;
  inside_holds_inverse : bool;
  patch : bool;
  sturm : sturm;
  scale_by_matrix : bool;
}

let default =
  {
    name = "";
    costly = true;
    box_test_free = false;
    inverse_flag = true;
    inside_holds_inverse = false;
    patch = false;
    sturm = No_sturm;
    scale_by_matrix = false;
  }
