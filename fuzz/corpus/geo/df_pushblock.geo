<?xml version="1.0" standalone="no"?>
<!-- A 1 m x 1 m block (type 2 sides) on a 4 m x 1 m base (type 1 outline),
     the base held by two fixed points; a load point and a measured point at
     the centre of the block. The analysis is df_pushblock.ana. -->
<!DOCTYPE DDA SYSTEM "geometry.dtd">
<Berkeley:DDA xmlns:Berkeley="http://www.tsoft.com/~bdoolin/dda">
<Berkeley:Geometry>
   <Berkeley:Edgenodedist distance="0.001"/>
   <Jointlist>
      <Joint type="1"> 0 0 4 0 </Joint>
      <Joint type="1"> 4 0 4 1 </Joint>
      <Joint type="1"> 4 1 0 1 </Joint>
      <Joint type="1"> 0 1 0 0 </Joint>
      <Joint type="2"> 1.5 1 1.5 2 </Joint>
      <Joint type="2"> 1.5 2 2.5 2 </Joint>
      <Joint type="2"> 2.5 2 2.5 1 </Joint>
   </Jointlist>
   <Fixedpointlist>
      <Point> 0.5 0.5 </Point>
      <Point> 3.5 0.5 </Point>
   </Fixedpointlist>
   <Loadpointlist>
      <Point> 2 1.5 </Point>
   </Loadpointlist>
   <Measuredpointlist>
      <Point> 2 1.5 </Point>
   </Measuredpointlist>
</Berkeley:Geometry>
</Berkeley:DDA>
