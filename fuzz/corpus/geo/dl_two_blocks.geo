<?xml version="1.0" standalone="no"?>
<!-- A 2 m x 1 m box split into two blocks by a vertical joint (type 2) at x = 1.
     One measured point in the left block, one fixed point in the right block. -->
<!DOCTYPE DDA SYSTEM "geometry.dtd">
<Berkeley:DDA xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda">
<Berkeley:Geometry>
   <Berkeley:Edgenodedist distance="0.01"/>
   <Jointlist>
      <Joint type="1"> 0 0 2 0 </Joint>
      <Joint type="1"> 2 0 2 1 </Joint>
      <Joint type="1"> 2 1 0 1 </Joint>
      <Joint type="1"> 0 1 0 0 </Joint>
      <Joint type="2"> 1 0 1 1 </Joint>
   </Jointlist>
   <Fixedpointlist>
      <Point> 1.5 0.5 </Point>
   </Fixedpointlist>
   <Measuredpointlist>
      <Point> 0.5 0.5 </Point>
   </Measuredpointlist>
</Berkeley:Geometry>
</Berkeley:DDA>
