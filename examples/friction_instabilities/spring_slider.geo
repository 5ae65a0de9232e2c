<?xml version="1.0" standalone="no"?>
<!-- The spring-slider of examples/friction_instabilities: a base
     [-1.5, 2.5] x [-0.5, 0] (type 1), a slider [0, 1] x [0, 0.5] on it
     (type 2 sides; its bottom is the base's top) and a driver block
     [3.0, 3.2] x [0, 0.2] beside the base (type 3), which a moving fixed
     point carries and which pulls the slider through a spring (a bolt).
     The points are named in the scenarios (make_cases.py). -->
<!DOCTYPE DDA SYSTEM "geometry.dtd">
<Berkeley:DDA xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda">
<Berkeley:Geometry>
   <Jointlist>
      <Joint type="1"> -1.5 -0.5 2.5 -0.5 </Joint>
      <Joint type="1"> 2.5 -0.5 2.5 0 </Joint>
      <Joint type="1"> 2.5 0 -1.5 0 </Joint>
      <Joint type="1"> -1.5 0 -1.5 -0.5 </Joint>
      <Joint type="2"> 0 0 0 0.5 </Joint>
      <Joint type="2"> 0 0.5 1 0.5 </Joint>
      <Joint type="2"> 1 0.5 1 0 </Joint>
      <Joint type="3"> 3.0 0 3.2 0 </Joint>
      <Joint type="3"> 3.2 0 3.2 0.2 </Joint>
      <Joint type="3"> 3.2 0.2 3.0 0.2 </Joint>
      <Joint type="3"> 3.0 0.2 3.0 0 </Joint>
   </Jointlist>
</Berkeley:Geometry>
</Berkeley:DDA>
