(** The camera (docs/povray-rules.md §1.4, §18.4): made once for a render from the compiled
    scene's camera and the image's size, it turns a position on the image into the camera ray
    through it (POV-Ray's TracePixel::CreateCameraRay): where the ray starts, its unit direction,
    and the interiors it starts in (§6.4). Each projection is a case of its own with its own
    function; a new projection is a new case, and the render loop does not change. *)

type t
(** A camera ready to make rays for an image of a given size. *)

val make : Compiled.t -> robust:bool -> width:int -> height:int -> t
(** [make scene ~robust ~width ~height] is [scene]'s camera for a [width]×[height] image (the
    whole image's size, even when only part of it is rendered); [robust] gives the rays' interior
    lists in the robust mode's order ({!Interiors.innermost_first}) instead of POV-Ray's. *)

val ray : t -> Context.t -> float -> float -> (Context.t -> int list -> Vec.t -> Vec.t -> 'a) -> 'a
(** [ray cam ctx x y k] is [k ctx interiors origin dir] for the camera ray through the image
    position (x, y): it starts at [origin] inside [interiors] (last entered first) and runs along
    the unit direction [dir]. The ray is handed to [k] as it is made, so that none is allocated
    per sample. Columns run 0 … width − 1 left to right, rows 0 … height − 1 top to bottom, an
    integer position a pixel's centre (fractional ones come from antialiasing). A perspective
    camera's rays leave its location along direction + x0·right + y0·up, and share the interiors
    that hold the location; an orthographic camera's rays leave the point
    location + x0·right + y0·up of its screen along its direction, each with the interiors that
    hold its own origin (found with the worker [ctx]'s traversal room). x0 and y0 run from −½ to
    ½ across the image (§1.4). *)
