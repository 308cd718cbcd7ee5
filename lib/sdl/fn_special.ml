(* Vector functions of splines, pigments and transforms, and pattern functions. *)

let terms_value t = if Array.length t = 5 then Value.Colour t else Value.Vector t

let spline s floc =
  let n = Spline.terms s in
  let veval fr = Array.sub (Spline.eval s fr.(0)) 0 n in
  { Fn.name = ""; params = [| "t" |]; frame = 1; size = n; eval = (fun fr -> (veval fr).(0)); veval; floc }

let spline_value s t = terms_value (Array.sub (Spline.eval s t) 0 (Spline.terms s))
