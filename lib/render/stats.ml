(* Render statistics: the counters one worker keeps, and their sum over workers. *)

type t = {
  mutable camera_rays : int;
  mutable reflected_rays : int;
  mutable refracted_rays : int;
  mutable shadow_rays : int;
  mutable sphere_tests : int;
  mutable sphere_hits : int;
  mutable plane_tests : int;
  mutable plane_hits : int;
  mutable triangle_tests : int;
  mutable triangle_hits : int;
  mutable mesh_tests : int;
  mutable mesh_hits : int;
  mutable box_tests : int;
  mutable box_hits : int;
  mutable cone_tests : int;
  mutable cone_hits : int;
  mutable disc_tests : int;
  mutable disc_hits : int;
  mutable torus_tests : int;
  mutable torus_hits : int;
  mutable torus_bound_hits : int;
  mutable roots_tested : int;
  mutable roots_eliminated : int;
  mutable max_level : int;
  mutable samples : int;
  mutable csg_union_tests : int;
  mutable csg_union_hits : int;
  mutable csg_intersection_tests : int;
  mutable csg_intersection_hits : int;
  mutable csg_merge_tests : int;
  mutable csg_merge_hits : int;
  mutable ttf_tests : int;
  mutable ttf_hits : int;
  mutable polygon_tests : int;
  mutable polygon_hits : int;
  mutable quadric_tests : int;
  mutable quadric_hits : int;
  mutable bound_tests : int;
  mutable bound_hits : int;
  mutable blob_tests : int;
  mutable blob_hits : int;
  mutable blob_element_tests : int;
  mutable blob_element_hits : int;
  mutable blob_bound_tests : int;
  mutable blob_bound_hits : int;
  mutable poly_tests : int;
  mutable poly_hits : int;
}

let create () =
  {
    camera_rays = 0; reflected_rays = 0; refracted_rays = 0; shadow_rays = 0; sphere_tests = 0;
    sphere_hits = 0; plane_tests = 0; plane_hits = 0; triangle_tests = 0; triangle_hits = 0; mesh_tests = 0; mesh_hits = 0; box_tests = 0; box_hits = 0; cone_tests = 0; cone_hits = 0; disc_tests = 0; disc_hits = 0;
    torus_tests = 0; torus_hits = 0; torus_bound_hits = 0; roots_tested = 0; roots_eliminated = 0; max_level = 0; samples = 0;
    csg_union_tests = 0; csg_union_hits = 0; csg_intersection_tests = 0; csg_intersection_hits = 0; csg_merge_tests = 0;
    csg_merge_hits = 0; ttf_tests = 0; ttf_hits = 0;
    polygon_tests = 0; polygon_hits = 0; quadric_tests = 0; quadric_hits = 0;
    bound_tests = 0; bound_hits = 0;
    blob_tests = 0; blob_hits = 0; blob_element_tests = 0; blob_element_hits = 0; blob_bound_tests = 0; blob_bound_hits = 0;
    poly_tests = 0; poly_hits = 0;
  }

let merge a b =
  {
    camera_rays = a.camera_rays + b.camera_rays;
    reflected_rays = a.reflected_rays + b.reflected_rays;
    refracted_rays = a.refracted_rays + b.refracted_rays;
    shadow_rays = a.shadow_rays + b.shadow_rays;
    sphere_tests = a.sphere_tests + b.sphere_tests;
    sphere_hits = a.sphere_hits + b.sphere_hits;
    plane_tests = a.plane_tests + b.plane_tests;
    plane_hits = a.plane_hits + b.plane_hits;
    triangle_tests = a.triangle_tests + b.triangle_tests;
    triangle_hits = a.triangle_hits + b.triangle_hits;
    mesh_tests = a.mesh_tests + b.mesh_tests;
    mesh_hits = a.mesh_hits + b.mesh_hits;
    box_tests = a.box_tests + b.box_tests;
    box_hits = a.box_hits + b.box_hits;
    cone_tests = a.cone_tests + b.cone_tests;
    cone_hits = a.cone_hits + b.cone_hits;
    disc_tests = a.disc_tests + b.disc_tests;
    disc_hits = a.disc_hits + b.disc_hits;
    torus_tests = a.torus_tests + b.torus_tests;
    torus_hits = a.torus_hits + b.torus_hits;
    torus_bound_hits = a.torus_bound_hits + b.torus_bound_hits;
    roots_tested = a.roots_tested + b.roots_tested;
    roots_eliminated = a.roots_eliminated + b.roots_eliminated;
    max_level = max a.max_level b.max_level;
    samples = a.samples + b.samples;
    csg_union_tests = a.csg_union_tests + b.csg_union_tests;
    csg_union_hits = a.csg_union_hits + b.csg_union_hits;
    csg_intersection_tests = a.csg_intersection_tests + b.csg_intersection_tests;
    csg_intersection_hits = a.csg_intersection_hits + b.csg_intersection_hits;
    csg_merge_tests = a.csg_merge_tests + b.csg_merge_tests;
    ttf_tests = a.ttf_tests + b.ttf_tests;
    ttf_hits = a.ttf_hits + b.ttf_hits;
    csg_merge_hits = a.csg_merge_hits + b.csg_merge_hits;
    polygon_tests = a.polygon_tests + b.polygon_tests;
    polygon_hits = a.polygon_hits + b.polygon_hits;
    quadric_tests = a.quadric_tests + b.quadric_tests;
    quadric_hits = a.quadric_hits + b.quadric_hits;
    bound_tests = a.bound_tests + b.bound_tests;
    bound_hits = a.bound_hits + b.bound_hits;
    blob_tests = a.blob_tests + b.blob_tests;
    blob_hits = a.blob_hits + b.blob_hits;
    blob_element_tests = a.blob_element_tests + b.blob_element_tests;
    blob_element_hits = a.blob_element_hits + b.blob_element_hits;
    blob_bound_tests = a.blob_bound_tests + b.blob_bound_tests;
    blob_bound_hits = a.blob_bound_hits + b.blob_bound_hits;
    poly_tests = a.poly_tests + b.poly_tests;
    poly_hits = a.poly_hits + b.poly_hits;
  }

type row = { name : string; tests : int; hits : int }
