<?xml version="1.0" standalone="no"?>
<!-- A 3 m x 2 m grid of six unit blocks (all type 1 joints), a fixed line
     along y = 0.5 through the bottom row (x 0.5 .. 2.5), a load point, a
     measured point and a hole point. -->
<!DOCTYPE DDA SYSTEM "geometry.dtd">
<Berkeley:DDA xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda">
<Berkeley:Geometry>
   <Berkeley:Edgenodedist distance="0.01"/>
   <Jointlist>
      <Joint type="1"> 0 0 3 0 </Joint>
      <Joint type="1"> 0 1 3 1 </Joint>
      <Joint type="1"> 0 2 3 2 </Joint>
      <Joint type="1"> 0 0 0 2 </Joint>
      <Joint type="1"> 1 0 1 2 </Joint>
      <Joint type="1"> 2 0 2 2 </Joint>
      <Joint type="1"> 3 0 3 2 </Joint>
   </Jointlist>
   <Fixedpointlist>
      <Line> 0.5 0.5 2.5 0.5 </Line>
   </Fixedpointlist>
   <Loadpointlist>
      <Point> 1.5 1.5 </Point>
   </Loadpointlist>
   <Measuredpointlist>
      <Point> 2.5 1.5 </Point>
   </Measuredpointlist>
<!--
   <Measuredpointlist>
      <Point> 9 9 </Point>
   </Measuredpointlist>
-->
   <Holepointlist>
      <Point> 0.5 1.5 </Point>
   </Holepointlist>
</Berkeley:Geometry>
</Berkeley:DDA>
