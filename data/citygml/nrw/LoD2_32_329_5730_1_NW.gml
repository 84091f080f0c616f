<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<core:CityModel xmlns="http://www.opengis.net/citygml/1.0" xmlns:core="http://www.opengis.net/citygml/1.0" xmlns:gen="http://www.opengis.net/citygml/generics/1.0" xmlns:grp="http://www.opengis.net/citygml/cityobjectgroup/1.0" xmlns:app="http://www.opengis.net/citygml/appearance/1.0" xmlns:bldg="http://www.opengis.net/citygml/building/1.0" xmlns:gml="http://www.opengis.net/gml" xmlns:xAL="urn:oasis:names:tc:ciq:xsdschema:xAL:2.0" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.opengis.net/citygml/1.0 http://repository.gdi-de.org/schemas/adv/citygml/1.0/cityGMLBaseLoD2.xsd http://www.opengis.net/citygml/building/1.0 http://repository.gdi-de.org/schemas/adv/citygml/building/1.0/buildingLoD2.xsd http://www.opengis.net/citygml/appearance/1.0 http://repository.gdi-de.org/schemas/adv/citygml/appearance/1.0/appearanceLoD2.xsd http://www.opengis.net/citygml/generics/1.0 http://repository.gdi-de.org/schemas/adv/citygml/generics/1.0/genericsLoD2.xsd http://www.opengis.net/citygml/cityobjectgroup/1.0 http://repository.gdi-de.org/schemas/adv/citygml/cityobjectgroup/1.0/cityObjectGroupLoD2.xsd">
  <gml:name>LoD2_32_329_5730_1_NW</gml:name>
  <gml:boundedBy>
    <gml:Envelope srsName="urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH*GCG2016">
      <gml:lowerCorner srsDimension="3">329000.0 5730000.0 18.308</gml:lowerCorner>
      <gml:upperCorner srsDimension="3">330000.0 5731000.0 29.913</gml:upperCorner>
    </gml:Envelope>
  </gml:boundedBy>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0002la7S">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0002la7S</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2723</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.481</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012009_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012009_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012009_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012009_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012009_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012009_2_3"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329237.302 5730717.16 22.46 329237.314 5730717.0 22.459 329237.361 5730716.361 22.442 329237.388 5730716.0 22.433 329237.43 5730715.43 22.436 329237.462 5730715.0 22.428 329237.499 5730714.499 22.41 329237.536 5730714.0 22.381 329237.568 5730713.568 22.377 329237.61 5730713.0 22.378 329237.637 5730712.637 22.39 329237.684 5730712.0 22.404 329237.705 5730711.705 22.404 329237.757 5730711.008 22.39</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329234.308 5730710.753 22.4 329234.789 5730710.789 22.396 329235.0 5730710.804 22.398 329235.868 5730710.868 22.416 329236.0 5730710.878 22.419 329236.948 5730710.948 22.391 329237.0 5730710.952 22.391 329237.649 5730711.0 22.39 329237.757 5730711.008 22.39</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329233.853 5730716.905 22.503 329233.857 5730716.857 22.503 329233.92 5730716.0 22.497 329233.925 5730715.925 22.496 329233.994 5730715.0 22.45 329233.994 5730714.994 22.45 329234.0 5730714.917 22.452 329234.063 5730714.063 22.478 329234.068 5730714.0 22.477 329234.132 5730713.132 22.457 329234.142 5730713.0 22.459 329234.201 5730712.201 22.442 329234.216 5730712.0 22.438 329234.27 5730711.27 22.415 329234.29 5730711.0 22.407 329234.308 5730710.753 22.4</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329233.853 5730716.905 22.503 329233.909 5730716.909 22.505 329234.0 5730716.916 22.509 329234.989 5730716.989 22.54 329235.0 5730716.99 22.54 329235.138 5730717.0 22.537 329236.0 5730717.064 22.519 329236.069 5730717.069 22.519 329237.0 5730717.138 22.45 329237.149 5730717.149 22.45 329237.302 5730717.16 22.46</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_7a57c9ff-1eb8-4f7d-a7ff-bdc448abceb1">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_2e5b56eb-0ba7-4855-bdc9-7c05527638ce">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012009_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012009_2_1_0_">
                      <gml:posList srsDimension="3">329237.302 5730717.16 24.858 329237.757 5730711.008 24.858 329237.757 5730711.008 22.377 329237.302 5730717.16 22.377 329237.302 5730717.16 24.858</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_c904a678-f645-48f8-88f2-b3d5783c5040">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_fca41d08-bc12-4792-9d93-e725d7720ecc">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012009_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012009_2_2_0_">
                      <gml:posList srsDimension="3">329237.757 5730711.008 24.858 329234.308 5730710.753 24.858 329234.308 5730710.753 22.377 329237.757 5730711.008 22.377 329237.757 5730711.008 24.858</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ee1ce38a-1226-42bb-93f8-5273786c8207">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_e3ca7e62-cdf0-4cdb-a629-1d5b35683512">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012009_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012009_2_3_0_">
                      <gml:posList srsDimension="3">329234.308 5730710.753 24.858 329233.853 5730716.905 24.858 329233.853 5730716.905 22.377 329234.308 5730710.753 22.377 329234.308 5730710.753 24.858</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_b6aa175b-c4f1-4f32-9422-f10bd9fc5790">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_40e1064a-854e-4264-b0f5-8bbe269e9b82">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012009_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012009_2_4_0_">
                      <gml:posList srsDimension="3">329233.853 5730716.905 24.858 329237.302 5730717.16 24.858 329237.302 5730717.16 22.377 329233.853 5730716.905 22.377 329233.853 5730716.905 24.858</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_25610f7b-a8b9-4300-9b18-d18cea964bd2">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_bc029449-cb2b-4e6a-a1cb-f94fdff5ec41">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012009_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012009_2_5_0_">
                      <gml:posList srsDimension="3">329233.853 5730716.905 24.858 329234.308 5730710.753 24.858 329237.757 5730711.008 24.858 329237.302 5730717.16 24.858 329233.853 5730716.905 24.858</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_75c1c6e2-1721-41ce-a66f-7032af2eed6b">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_f1360ac8-5443-4f6d-9d1e-73f617c0ac81">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012009_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012009_2_0_0_">
                      <gml:posList srsDimension="3">329237.302 5730717.16 22.377 329237.757 5730711.008 22.377 329234.308 5730710.753 22.377 329233.853 5730716.905 22.377 329237.302 5730717.16 22.377</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8R">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8R</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.632</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012019_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012019_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012019_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012019_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012019_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012019_2_0"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329178.102 5730502.653 18.816 329178.192 5730503.0 18.822 329178.26 5730503.26 18.839 329178.453 5730504.0 18.887 329178.612 5730504.612 18.884 329178.713 5730505.0 18.883 329178.965 5730505.965 18.917 329178.974 5730506.0 18.918 329179.0 5730506.1 18.919 329179.234 5730507.0 18.91 329179.317 5730507.317 18.9 329179.495 5730508.0 18.88 329179.669 5730508.669 18.88 329179.755 5730509.0 18.88 329180.0 5730509.939 18.871 329180.016 5730510.0 18.87 329180.021 5730510.021 18.87 329180.276 5730511.0 18.864 329180.374 5730511.374 18.863 329180.493 5730511.832 18.833</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329180.493 5730511.832 18.833 329180.757 5730511.757 18.855 329181.0 5730511.688 18.85 329181.536 5730511.536 18.839 329182.0 5730511.404 18.842 329182.315 5730511.315 18.847 329183.0 5730511.121 18.866 329183.094 5730511.094 18.872 329183.426 5730511.0 18.879 329183.873 5730510.873 18.89 329183.926 5730510.858 18.892</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329181.521 5730501.801 19.071 329181.574 5730502.0 19.073 329181.781 5730502.781 19.033 329181.839 5730503.0 19.034 329182.0 5730503.605 19.022 329182.105 5730504.0 19.011 329182.143 5730504.143 19.009 329182.37 5730505.0 18.987 329182.504 5730505.504 18.985 329182.636 5730506.0 18.979 329182.866 5730506.866 18.96 329182.902 5730507.0 18.958 329183.0 5730507.371 18.949 329183.167 5730508.0 18.933 329183.227 5730508.227 18.932 329183.433 5730509.0 18.923 329183.589 5730509.589 18.916 329183.698 5730510.0 18.911 329183.926 5730510.858 18.892</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329178.102 5730502.653 18.816 329178.543 5730502.543 18.843 329179.0 5730502.429 18.841 329179.344 5730502.344 18.861 329180.0 5730502.18 18.924 329180.144 5730502.144 18.932 329180.722 5730502.0 18.985 329180.945 5730501.945 19.007 329181.0 5730501.931 19.011 329181.521 5730501.801 19.071</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_3e883bd1-dae0-4180-a71d-493227403dd9">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_e95bae6c-a901-47c8-a70f-4b3197befc07">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012019_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012019_2_1_0_">
                      <gml:posList srsDimension="3">329178.102 5730502.653 21.449 329180.493 5730511.832 21.449 329180.493 5730511.832 18.816 329178.102 5730502.653 18.816 329178.102 5730502.653 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_6b78936e-c659-4a72-884c-467f35916972">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_70e690a8-4d8b-488f-afb5-aacf9f775c50">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012019_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012019_2_2_0_">
                      <gml:posList srsDimension="3">329180.493 5730511.832 21.449 329183.926 5730510.858 21.449 329183.926 5730510.858 18.816 329180.493 5730511.832 18.816 329180.493 5730511.832 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_baa6905f-0483-456e-92b7-3ec778592fed">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_15bb23bb-a5c3-426b-b782-e12d2a6e1f90">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012019_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012019_2_3_0_">
                      <gml:posList srsDimension="3">329183.926 5730510.858 21.449 329181.521 5730501.801 21.449 329181.521 5730501.801 18.816 329183.926 5730510.858 18.816 329183.926 5730510.858 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_dd24f4e5-fb07-41a2-ab6a-8d9d0668d5a4">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_4b668b22-8fea-494a-9f8b-c4bbe6d1d3de">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012019_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012019_2_4_0_">
                      <gml:posList srsDimension="3">329181.521 5730501.801 21.449 329178.102 5730502.653 21.449 329178.102 5730502.653 18.816 329181.521 5730501.801 18.816 329181.521 5730501.801 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_5bc7d7ce-566f-4d8e-8ce5-837dffed9595">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_9468152c-ea1a-4d4c-bb17-7aaeebcbba03">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012019_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012019_2_5_0_">
                      <gml:posList srsDimension="3">329181.521 5730501.801 21.449 329183.926 5730510.858 21.449 329180.493 5730511.832 21.449 329178.102 5730502.653 21.449 329181.521 5730501.801 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_7fe3c483-7371-4e56-bfb6-d7cb26c831b6">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_44c4efbe-08a2-411f-b406-d36577d9a2c9">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012019_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012019_2_0_0_">
                      <gml:posList srsDimension="3">329178.102 5730502.653 18.816 329180.493 5730511.832 18.816 329183.926 5730510.858 18.816 329181.521 5730501.801 18.816 329178.102 5730502.653 18.816</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_41896284-13a4-450f-a5eb-1401782dc924">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8T">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8T</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.745</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012010_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012010_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012010_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012010_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012010_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012010_2_5"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329184.984 5730515.494 18.829 329185.0 5730515.49 18.831 329185.395 5730515.395 18.88 329186.0 5730515.248 18.918 329186.2 5730515.2 18.934 329187.0 5730515.006 18.96 329187.005 5730515.005 18.96 329187.026 5730515.0 18.96 329187.81 5730514.81 18.972 329188.0 5730514.765 18.979 329188.616 5730514.616 18.998 329189.0 5730514.523 19.043 329189.292 5730514.452 19.059</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329188.149 5730509.745 19.079 329188.211 5730510.0 19.078 329188.279 5730510.279 19.078 329188.454 5730511.0 19.084 329188.599 5730511.599 19.076 329188.697 5730512.0 19.074 329188.92 5730512.92 19.051 329188.939 5730513.0 19.049 329189.0 5730513.25 19.062 329189.182 5730514.0 19.109 329189.241 5730514.241 19.081 329189.292 5730514.452 19.059</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329183.926 5730510.858 18.892 329184.0 5730510.838 18.895 329184.664 5730510.664 18.933 329185.0 5730510.575 18.949 329185.455 5730510.455 18.974 329186.0 5730510.311 18.997 329186.246 5730510.246 19.007 329187.0 5730510.048 19.03 329187.038 5730510.038 19.032 329187.181 5730510.0 19.037 329187.829 5730509.829 19.065 329188.0 5730509.784 19.072 329188.149 5730509.745 19.079</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329183.926 5730510.858 18.892 329183.946 5730510.946 18.89 329183.958 5730511.0 18.889 329184.0 5730511.182 18.89 329184.187 5730512.0 18.899 329184.242 5730512.242 18.905 329184.415 5730513.0 18.909 329184.537 5730513.537 18.907 329184.643 5730514.0 18.912 329184.833 5730514.833 18.88 329184.871 5730515.0 18.865 329184.984 5730515.494 18.829</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_1e8a264a-c203-4f6a-b8ca-feb2b2f87a2b">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_655bf1bd-818d-4e84-8199-7c4c4ccd16c4">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012010_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012010_2_1_0_">
                      <gml:posList srsDimension="3">329184.984 5730515.494 21.574 329189.292 5730514.452 21.574 329189.292 5730514.452 18.829 329184.984 5730515.494 18.829 329184.984 5730515.494 21.574</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_1138900b-7845-4cf3-88b4-ea4d2bc46389">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_a9d813b3-58d9-4bdd-bf76-2e07bf11de3d">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012010_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012010_2_2_0_">
                      <gml:posList srsDimension="3">329189.292 5730514.452 21.574 329188.149 5730509.745 21.574 329188.149 5730509.745 18.829 329189.292 5730514.452 18.829 329189.292 5730514.452 21.574</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_1913f579-de6d-429d-bfbe-c46a64619773">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c524a8e4-39c0-4387-ac61-47948081bf33">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012010_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012010_2_3_0_">
                      <gml:posList srsDimension="3">329188.149 5730509.745 21.574 329183.926 5730510.858 21.574 329183.926 5730510.858 18.829 329188.149 5730509.745 18.829 329188.149 5730509.745 21.574</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ae102185-0308-4f8a-8c67-a75bb27cbc97">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_69a6c55e-4d7e-4be1-915c-b08901892ed2">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012010_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012010_2_4_0_">
                      <gml:posList srsDimension="3">329183.926 5730510.858 21.574 329184.984 5730515.494 21.574 329184.984 5730515.494 18.829 329183.926 5730510.858 18.829 329183.926 5730510.858 21.574</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_557fff3f-166c-4ffd-a8e9-2eb1e228d898">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_fdec5a5b-8198-458f-bc4b-4d20d0007ae3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012010_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012010_2_5_0_">
                      <gml:posList srsDimension="3">329183.926 5730510.858 21.574 329188.149 5730509.745 21.574 329189.292 5730514.452 21.574 329184.984 5730515.494 21.574 329183.926 5730510.858 21.574</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_5ab52c35-6833-4906-a208-5b22e4ac021f">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_f5717823-01c3-4df3-bf8a-7950df0478d7">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012010_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012010_2_0_0_">
                      <gml:posList srsDimension="3">329184.984 5730515.494 18.829 329189.292 5730514.452 18.829 329188.149 5730509.745 18.829 329183.926 5730510.858 18.829 329184.984 5730515.494 18.829</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_d8148b9c-c2a6-41cb-831b-374a39f0b80c">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000rD7U">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000rD7U</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>51009_1610</bldg:function>
      <bldg:roofType>2100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">3.609</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_6"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012020_2_7"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329286.216 5730989.926 21.198 329286.264 5730990.0 21.197 329286.743 5730990.743 21.141 329286.909 5730991.0 21.128 329287.0 5730991.142 21.131 329287.554 5730992.0 21.172 329287.836 5730992.438 21.132</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329287.836 5730992.438 21.132 329288.0 5730992.33 21.13 329288.199 5730992.199 21.132 329288.503 5730992.0 21.125 329288.803 5730991.803 21.11 329289.0 5730991.674 21.103 329289.407 5730991.407 21.09 329290.0 5730991.017 21.089 329290.01 5730991.01 21.09 329290.026 5730991.0 21.089 329290.614 5730990.614 21.089 329291.0 5730990.36 21.064 329291.218 5730990.218 21.06 329291.549 5730990.0 21.076 329291.821 5730989.821 21.092 329292.0 5730989.704 21.102 329292.365 5730989.464 21.115</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329292.3 5730989.355 21.119 329292.365 5730989.464 21.115</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329292.3 5730989.355 21.119 329292.333 5730989.333 21.12 329292.839 5730989.0 21.122 329292.936 5730988.936 21.123 329293.0 5730988.894 21.126 329293.539 5730988.539 21.148 329294.0 5730988.236 21.151 329294.142 5730988.142 21.157 329294.359 5730988.0 21.156 329294.745 5730987.745 21.147 329295.0 5730987.578 21.154 329295.349 5730987.349 21.15 329295.837 5730987.027 21.143</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329294.282 5730984.65 21.162 329294.511 5730985.0 21.164 329295.0 5730985.748 21.14 329295.165 5730986.0 21.135 329295.478 5730986.478 21.14 329295.819 5730987.0 21.144 329295.837 5730987.027 21.143</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329286.216 5730989.926 21.198 329286.645 5730989.645 21.194 329287.0 5730989.413 21.19 329287.25 5730989.25 21.188 329287.632 5730989.0 21.177 329287.854 5730988.854 21.171 329288.0 5730988.759 21.17 329288.459 5730988.459 21.165 329289.0 5730988.105 21.178 329289.063 5730988.063 21.178 329289.16 5730988.0 21.175 329289.668 5730987.668 21.167 329290.0 5730987.451 21.155 329290.273 5730987.273 21.16 329290.689 5730987.0 21.188 329290.877 5730986.877 21.2 329291.0 5730986.797 21.196 329291.482 5730986.482 21.19 329292.0 5730986.143 21.166 329292.086 5730986.086 21.164 329292.218 5730986.0 21.16 329292.691 5730985.691 21.151 329293.0 5730985.489 21.155 329293.295 5730985.295 21.156 329293.747 5730985.0 21.18 329293.9 5730984.9 21.182 329294.0 5730984.834 21.183 329294.282 5730984.65 21.162</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_5df96ea4-1cb7-46f9-9995-a0dc570c81ea">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_dabcbe81-97b6-4aa8-9799-1caa129cd1d5">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_1_0_">
                      <gml:posList srsDimension="3">329286.216 5730989.926 23.911 329287.836 5730992.438 24.669 329287.836 5730992.438 21.06 329286.216 5730989.926 21.06 329286.216 5730989.926 23.911</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_8fa2318c-1431-4779-b76a-68453694bd14">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_401604c6-83bc-4560-bb0e-6464a609906a">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_2_0_">
                      <gml:posList srsDimension="3">329287.836 5730992.438 24.669 329292.365 5730989.464 24.666 329292.365 5730989.464 21.06 329287.836 5730992.438 21.06 329287.836 5730992.438 24.669</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_eae30948-d024-4f48-b7eb-fe8c96ad7673">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_29bd2aee-7bbe-487c-a07b-c22f7aef01fd">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_3_0_">
                      <gml:posList srsDimension="3">329292.365 5730989.464 24.666 329292.3 5730989.355 24.634 329292.3 5730989.355 21.06 329292.365 5730989.464 21.06 329292.365 5730989.464 24.666</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_95d5bd0b-ec79-429f-abb4-9eb5ec445637">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_8225a8c8-1325-44b4-a989-8b662482bf6e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_4_0_">
                      <gml:posList srsDimension="3">329292.3 5730989.355 24.634 329295.837 5730987.027 24.631 329295.837 5730987.027 21.06 329292.3 5730989.355 21.06 329292.3 5730989.355 24.634</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_4bb03425-3301-4c3b-8e5f-0f974a822442">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_848e5967-cd87-4344-b618-f6f818091fcf">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_5_0_">
                      <gml:posList srsDimension="3">329295.837 5730987.027 24.631 329294.282 5730984.65 23.911 329294.282 5730984.65 21.06 329295.837 5730987.027 21.06 329295.837 5730987.027 24.631</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_9b00445e-d1d9-44d3-ab1a-4c94c1b39b70">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_ca83e28b-477e-4d38-a075-818345b34a8f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_6_0_">
                      <gml:posList srsDimension="3">329294.282 5730984.65 23.911 329286.216 5730989.926 23.911 329286.216 5730989.926 21.06 329294.282 5730984.65 21.06 329294.282 5730984.65 23.911</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_2d155fec-2b47-4f11-a505-96891318181e">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_77d9fc2c-f28d-4531-887f-4eee85345310">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_7">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_7_0_">
                      <gml:posList srsDimension="3">329294.282 5730984.65 23.911 329295.837 5730987.027 24.631 329292.3 5730989.355 24.634 329292.365 5730989.464 24.666 329287.836 5730992.438 24.669 329286.216 5730989.926 23.911 329294.282 5730984.65 23.911</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_744e86db-e134-4f99-86fd-bddd309640da">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c49bf3f1-1317-4d35-a984-c40cbd2cfb3e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012020_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012020_2_0_0_">
                      <gml:posList srsDimension="3">329286.216 5730989.926 21.06 329287.836 5730992.438 21.06 329292.365 5730989.464 21.06 329292.3 5730989.355 21.06 329295.837 5730987.027 21.06 329294.282 5730984.65 21.06 329286.216 5730989.926 21.06</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8U">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8U</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">6.105</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_6"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_8"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_7"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012011_2_0"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329189.15 5730496.961 19.076 329189.865 5730496.865 19.06 329190.0 5730496.846 19.058 329190.746 5730496.746 19.05 329191.0 5730496.711 19.044 329191.627 5730496.627 19.03 329192.0 5730496.577 19.026 329192.508 5730496.508 19.03 329193.0 5730496.442 19.04 329193.389 5730496.389 19.059 329194.0 5730496.307 19.069 329194.27 5730496.27 19.071 329195.0 5730496.172 19.092 329195.151 5730496.151 19.09 329196.0 5730496.037 19.08 329196.033 5730496.033 19.08 329196.274 5730496.0 19.077 329196.914 5730495.914 19.071 329197.0 5730495.902 19.07 329197.795 5730495.795 19.07 329198.0 5730495.767 19.07 329198.068 5730495.758 19.07</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329197.296 5730490.045 19.073 329197.335 5730490.335 19.073 329197.425 5730491.0 19.08 329197.491 5730491.491 19.08 329197.56 5730492.0 19.076 329197.648 5730492.648 19.07 329197.695 5730493.0 19.07 329197.804 5730493.804 19.07 329197.83 5730494.0 19.07 329197.96 5730494.96 19.07 329197.966 5730495.0 19.07 329198.0 5730495.255 19.07 329198.068 5730495.758 19.07</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329188.363 5730491.217 18.955 329189.0 5730491.133 18.945 329189.118 5730491.118 18.945 329190.0 5730491.002 18.95 329190.002 5730491.002 18.95 329190.017 5730491.0 18.95 329190.886 5730490.886 18.942 329191.0 5730490.871 18.944 329191.77 5730490.77 18.939 329192.0 5730490.74 18.929 329192.654 5730490.654 18.916 329193.0 5730490.609 18.936 329193.538 5730490.538 18.952 329194.0 5730490.477 18.954 329194.422 5730490.422 18.978 329195.0 5730490.346 19.004 329195.306 5730490.306 19.014 329196.0 5730490.215 19.039 329196.19 5730490.19 19.04 329197.0 5730490.084 19.071 329197.074 5730490.074 19.071 329197.296 5730490.045 19.073</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329188.363 5730491.217 18.955 329188.386 5730491.386 18.962 329188.47 5730492.0 18.98 329188.545 5730492.545 18.996 329188.607 5730493.0 19.01 329188.704 5730493.704 19.017 329188.744 5730494.0 19.025 329188.862 5730494.862 19.04 329188.881 5730495.0 19.042 329189.0 5730495.866 19.057 329189.018 5730496.0 19.06 329189.021 5730496.021 19.06 329189.15 5730496.961 19.076</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_009d01c9-f77f-4a00-9597-73ef2ee13d6c">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_142219f3-64a8-4f4b-819a-56121d1f7c95">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_1_0_">
                      <gml:posList srsDimension="3">329189.15 5730496.961 22.177 329198.068 5730495.758 22.177 329198.068 5730495.758 18.916 329189.15 5730496.961 18.916 329189.15 5730496.961 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_e04861e5-5b8e-4598-838a-9bc9edff93c5">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_862a33f7-c101-469c-aec4-3b64114c528f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_2_0_">
                      <gml:posList srsDimension="3">329198.068 5730495.758 22.177 329197.296 5730490.045 22.177 329197.296 5730490.045 18.916 329198.068 5730495.758 18.916 329198.068 5730495.758 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_9762af89-e084-4430-9a6b-d4a0de7a2210">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_4d54838e-6bcc-4753-8d92-86a2314cdcd3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_3_0_">
                      <gml:posList srsDimension="3">329197.296 5730490.045 22.177 329188.363 5730491.217 22.177 329188.363 5730491.217 18.916 329197.296 5730490.045 18.916 329197.296 5730490.045 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_2933df56-6a44-4596-bf2f-1eb8e0d03ce8">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_1d654b58-2c63-4304-a71d-7b4588318215">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_4_0_">
                      <gml:posList srsDimension="3">329188.363 5730491.217 22.177 329189.15 5730496.961 22.177 329189.15 5730496.961 18.916 329188.363 5730491.217 18.916 329188.363 5730491.217 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_77a8f87f-1803-4b96-a1ed-0b3edc690790">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_0dc088db-6b07-4529-9892-9d6a5ad064cb">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_5_0_">
                      <gml:posList srsDimension="3">329197.296 5730490.045 22.177 329198.068 5730495.758 22.177 329197.682 5730492.902 25.021 329197.296 5730490.045 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_4c9cd1fe-f415-4e48-a18d-5c69b6c4a2ca">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c20de98a-5736-4ffe-a50e-3cacc2e1ff42">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_6_0_">
                      <gml:posList srsDimension="3">329189.15 5730496.961 22.177 329188.363 5730491.217 22.177 329188.757 5730494.089 25.021 329189.15 5730496.961 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_29574063-74e8-455e-bb82-f9bcef62a625">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_091e9a8c-5c58-462f-9906-6c0b9e4ccfa9">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_7">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_7_0_">
                      <gml:posList srsDimension="3">329198.068 5730495.758 22.177 329189.15 5730496.961 22.177 329188.757 5730494.089 25.021 329197.682 5730492.902 25.021 329198.068 5730495.758 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_a7316d13-f916-4d69-986e-f3ab2f7075e2">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_9effebac-0f0f-4359-833f-82f35d3055f7">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_8">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_8_0_">
                      <gml:posList srsDimension="3">329188.363 5730491.217 22.177 329197.296 5730490.045 22.177 329197.682 5730492.902 25.021 329188.757 5730494.089 25.021 329188.363 5730491.217 22.177</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_8883ef3e-7a84-4e93-81dc-34440d2ee1ab">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_e786ddf5-321d-490e-ae0b-6c8f252b2df8">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012011_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012011_2_0_0_">
                      <gml:posList srsDimension="3">329189.15 5730496.961 18.916 329198.068 5730495.758 18.916 329197.296 5730490.045 18.916 329188.363 5730491.217 18.916 329189.15 5730496.961 18.916</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_3b8f0469-f628-4fe3-9657-8b5715492c23">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000rD7V">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000rD7V</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">5.859</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_8"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_7"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012023_2_6"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329326.988 5730991.589 21.068 329327.0 5730991.581 21.067 329327.347 5730991.347 21.067 329327.864 5730991.0 21.067 329327.945 5730990.945 21.067 329328.0 5730990.908 21.065 329328.543 5730990.543 21.053 329329.0 5730990.236 21.049 329329.141 5730990.141 21.047 329329.351 5730990.0 21.047 329329.739 5730989.739 21.05 329330.0 5730989.564 21.056 329330.337 5730989.337 21.067 329330.838 5730989.0 21.075 329330.935 5730988.935 21.076 329331.0 5730988.891 21.079 329331.533 5730988.533 21.091 329332.0 5730988.219 21.094 329332.131 5730988.131 21.097 329332.325 5730988.0 21.103 329332.729 5730987.729 21.114 329333.0 5730987.546 21.121 329333.327 5730987.327 21.136 329333.812 5730987.0 21.151 329333.925 5730986.925 21.155 329334.0 5730986.874 21.156 329334.523 5730986.523 21.161 329335.0 5730986.201 21.166 329335.12 5730986.12 21.162 329335.3 5730986.0 21.157 329335.718 5730985.718 21.144 329336.0 5730985.529 21.145 329336.316 5730985.316 21.127 329336.787 5730985.0 21.124 329336.914 5730984.914 21.121 329337.0 5730984.857 21.117 329337.512 5730984.512 21.074 329338.0 5730984.184 21.05 329338.11 5730984.11 21.041 329338.274 5730984.0 21.053 329338.491 5730983.854 21.055</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329334.577 5730978.034 20.943 329335.0 5730978.663 20.99 329335.227 5730979.0 20.995 329335.692 5730979.692 20.997 329335.899 5730980.0 21.0 329336.0 5730980.15 21.006 329336.572 5730981.0 21.029 329337.0 5730981.637 21.033 329337.244 5730982.0 21.033 329337.746 5730982.746 21.047 329337.917 5730983.0 21.052 329338.0 5730983.124 21.05 329338.491 5730983.854 21.055</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329323.042 5730985.72 20.831 329323.449 5730985.449 20.839 329324.0 5730985.082 20.822 329324.049 5730985.049 20.821 329324.123 5730985.0 20.822 329324.649 5730984.649 20.844 329325.0 5730984.415 20.822 329325.249 5730984.249 20.817 329325.623 5730984.0 20.822 329325.849 5730983.849 20.835 329326.0 5730983.749 20.827 329326.45 5730983.45 20.842 329327.0 5730983.083 20.833 329327.05 5730983.05 20.833 329327.124 5730983.0 20.834 329327.65 5730982.65 20.856 329328.0 5730982.416 20.837 329328.25 5730982.25 20.835 329328.625 5730982.0 20.826 329328.85 5730981.85 20.831 329329.0 5730981.75 20.825 329329.45 5730981.45 20.833 329330.0 5730981.084 20.823 329330.05 5730981.05 20.823 329330.126 5730981.0 20.824 329330.65 5730980.65 20.836 329331.0 5730980.417 20.838 329331.251 5730980.251 20.843 329331.626 5730980.0 20.855 329331.851 5730979.851 20.871 329332.0 5730979.751 20.858 329332.451 5730979.451 20.856 329333.0 5730979.085 20.863 329333.051 5730979.051 20.865 329333.127 5730979.0 20.866 329333.651 5730978.651 20.889 329334.0 5730978.418 20.893 329334.251 5730978.251 20.908 329334.577 5730978.034 20.943</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329323.042 5730985.72 20.831 329323.23 5730986.0 20.835 329323.703 5730986.703 20.858 329323.903 5730987.0 20.87 329324.0 5730987.145 20.876 329324.575 5730988.0 20.91 329325.0 5730988.632 20.935 329325.247 5730989.0 20.952 329325.755 5730989.755 20.98 329325.92 5730990.0 20.991 329326.0 5730990.12 20.997 329326.592 5730991.0 21.05 329326.988 5730991.589 21.068</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ecf7d8d2-937e-4232-8605-724464acfd1d">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_6f1b2ac9-4f6a-4b4e-90bc-cf852806c67f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_1_0_">
                      <gml:posList srsDimension="3">329326.988 5730991.589 23.897 329338.491 5730983.854 23.897 329338.491 5730983.854 20.817 329326.988 5730991.589 20.817 329326.988 5730991.589 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_5f99a396-b25c-4985-b161-19675e7b0e39">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c937d281-c8df-4ab8-99be-a58f85299c81">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_2_0_">
                      <gml:posList srsDimension="3">329338.491 5730983.854 23.897 329334.577 5730978.034 23.897 329334.577 5730978.034 20.817 329338.491 5730983.854 20.817 329338.491 5730983.854 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_59cde606-3f5c-42c9-8f1f-ac810aa34530">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_77ecfc0a-7bad-4d80-bb95-950136463bcb">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_3_0_">
                      <gml:posList srsDimension="3">329334.577 5730978.034 23.897 329323.042 5730985.72 23.897 329323.042 5730985.72 20.817 329334.577 5730978.034 20.817 329334.577 5730978.034 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_24554a88-ff55-453e-814c-45ac02141f93">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_462632cc-867f-4a91-acb4-beec726c60c8">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_4_0_">
                      <gml:posList srsDimension="3">329323.042 5730985.72 23.897 329326.988 5730991.589 23.897 329326.988 5730991.589 20.817 329323.042 5730985.72 20.817 329323.042 5730985.72 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ff79410a-abaa-474f-9c81-bbd629310e1b">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_f7da0ff1-87ff-4a58-8929-ef2b2d852e4c">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_5_0_">
                      <gml:posList srsDimension="3">329334.577 5730978.034 23.897 329338.491 5730983.854 23.897 329336.534 5730980.944 26.677 329334.577 5730978.034 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_8e49d133-3095-4ad9-8574-8e1122238b1a">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_14c116f9-ccef-4633-9874-5a9e8999c85d">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_6_0_">
                      <gml:posList srsDimension="3">329326.988 5730991.589 23.897 329323.042 5730985.72 23.897 329325.015 5730988.655 26.677 329326.988 5730991.589 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_cf77362e-d612-466f-a110-66032ba43a75">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c13b5f35-dc8a-41ef-b1bb-41097b788c01">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_7">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_7_0_">
                      <gml:posList srsDimension="3">329338.491 5730983.854 23.897 329326.988 5730991.589 23.897 329325.015 5730988.655 26.677 329336.534 5730980.944 26.677 329338.491 5730983.854 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_5c57c680-20c9-440c-bb59-28ebf2bb4c32">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_3fc5f82b-de18-439b-a3e7-734a013d2756">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_8">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_8_0_">
                      <gml:posList srsDimension="3">329323.042 5730985.72 23.897 329334.577 5730978.034 23.897 329336.534 5730980.944 26.677 329325.015 5730988.655 26.677 329323.042 5730985.72 23.897</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_4757473e-cd8f-4e1a-9f7b-ddabd3ee2d27">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_78ec6e67-9e0e-40d1-b7c4-ae4ba5ce5cfe">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012023_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012023_2_0_0_">
                      <gml:posList srsDimension="3">329326.988 5730991.589 20.817 329338.491 5730983.854 20.817 329334.577 5730978.034 20.817 329323.042 5730985.72 20.817 329326.988 5730991.589 20.817</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_b8c67dc8-053a-4b9f-8d6e-ee05f0e3013a">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>19</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0002la7V">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0002la7V</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2723</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.457</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012022_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012022_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012022_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012022_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012022_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012022_2_4"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329183.785 5730837.912 22.18 329183.801 5730838.0 22.188 329183.981 5730838.981 22.219 329183.985 5730839.0 22.22 329184.0 5730839.084 22.219 329184.168 5730840.0 22.213 329184.206 5730840.206 22.226 329184.352 5730841.0 22.251 329184.43 5730841.43 22.264 329184.535 5730842.0 22.268 329184.57 5730842.191 22.254</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329181.18 5730838.39 22.111 329181.357 5730838.357 22.118 329182.0 5730838.24 22.127 329182.202 5730838.202 22.136 329183.0 5730838.056 22.181 329183.047 5730838.047 22.182 329183.305 5730838.0 22.183 329183.785 5730837.912 22.18</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329181.18 5730838.39 22.111 329181.292 5730839.0 22.122 329181.357 5730839.357 22.124 329181.475 5730840.0 22.124 329181.582 5730840.582 22.123 329181.659 5730841.0 22.126 329181.807 5730841.807 22.124 329181.842 5730842.0 22.122 329181.965 5730842.669 22.128</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329181.965 5730842.669 22.128 329182.0 5730842.663 22.13 329182.56 5730842.56 22.136 329183.0 5730842.479 22.161 329183.405 5730842.405 22.172 329184.0 5730842.296 22.202 329184.25 5730842.25 22.22 329184.57 5730842.191 22.254</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_d93c37c1-b098-4c23-8322-80f05f24fff7">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_05a1eebe-8b71-4bdc-bb75-71b7dcc5f23f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012022_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012022_2_1_0_">
                      <gml:posList srsDimension="3">329184.57 5730842.191 24.568 329183.785 5730837.912 24.568 329183.785 5730837.912 22.111 329184.57 5730842.191 22.111 329184.57 5730842.191 24.568</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_86db63f2-3d76-4dfb-9ba4-c0223eb71795">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_855b3c55-703f-47ae-9a49-14f53e67d6b2">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012022_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012022_2_2_0_">
                      <gml:posList srsDimension="3">329183.785 5730837.912 24.568 329181.18 5730838.39 24.568 329181.18 5730838.39 22.111 329183.785 5730837.912 22.111 329183.785 5730837.912 24.568</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_b3768a40-4cee-4fd5-ab18-6ed1eda187ae">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_e102e0a4-9346-4dea-bac4-8e3f4def428b">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012022_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012022_2_3_0_">
                      <gml:posList srsDimension="3">329181.18 5730838.39 24.568 329181.965 5730842.669 24.568 329181.965 5730842.669 22.111 329181.18 5730838.39 22.111 329181.18 5730838.39 24.568</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_d3e3627b-36ca-40b4-9fc2-8498485bb694">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_72e76984-f6e8-4c85-8818-d7bb732c288e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012022_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012022_2_4_0_">
                      <gml:posList srsDimension="3">329181.965 5730842.669 24.568 329184.57 5730842.191 24.568 329184.57 5730842.191 22.111 329181.965 5730842.669 22.111 329181.965 5730842.669 24.568</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_4118cd61-00d4-45ca-88fb-5066915f648b">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_8d056f22-b579-4115-85c0-b574417c744f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012022_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012022_2_5_0_">
                      <gml:posList srsDimension="3">329181.965 5730842.669 24.568 329181.18 5730838.39 24.568 329183.785 5730837.912 24.568 329184.57 5730842.191 24.568 329181.965 5730842.669 24.568</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_142d3180-4963-4946-ac1e-ee2542f0fa57">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_6e231bad-d4ae-498b-9e56-ebf434f651a3">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012022_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012022_2_0_0_">
                      <gml:posList srsDimension="3">329184.57 5730842.191 22.111 329183.785 5730837.912 22.111 329181.18 5730838.39 22.111 329181.965 5730842.669 22.111 329184.57 5730842.191 22.111</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8W">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8W</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_1210</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.889</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012021_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012021_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012021_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012021_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012021_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012021_2_4"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329210.437 5730495.306 19.016 329211.0 5730495.244 18.997 329211.22 5730495.22 18.992 329212.0 5730495.135 18.974 329212.122 5730495.122 18.972 329213.0 5730495.026 18.951 329213.023 5730495.023 18.951 329213.235 5730495.0 18.948 329213.683 5730494.951 18.941</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329212.723 5730487.964 18.908 329212.728 5730488.0 18.908 329212.844 5730488.844 18.867 329212.865 5730489.0 18.867 329213.0 5730489.98 18.87 329213.003 5730490.0 18.87 329213.003 5730490.003 18.87 329213.14 5730491.0 18.876 329213.162 5730491.162 18.877 329213.278 5730492.0 18.86 329213.322 5730492.322 18.863 329213.415 5730493.0 18.882 329213.481 5730493.481 18.9 329213.552 5730494.0 18.91 329213.64 5730494.64 18.929 329213.683 5730494.951 18.941</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329209.495 5730488.348 18.808 329210.0 5730488.288 18.823 329210.257 5730488.257 18.825 329211.0 5730488.169 18.832 329211.151 5730488.151 18.833 329212.0 5730488.05 18.85 329212.045 5730488.045 18.851 329212.42 5730488.0 18.884 329212.723 5730487.964 18.908</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329209.495 5730488.348 18.808 329209.518 5730488.518 18.811 329209.583 5730489.0 18.83 329209.675 5730489.675 18.837 329209.719 5730490.0 18.843 329209.831 5730490.831 18.858 329209.854 5730491.0 18.866 329209.988 5730491.988 18.9 329209.989 5730492.0 18.9 329210.0 5730492.078 18.902 329210.125 5730493.0 18.928 329210.144 5730493.144 18.931 329210.26 5730494.0 18.992 329210.301 5730494.301 19.004 329210.396 5730495.0 19.008 329210.437 5730495.306 19.016</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_0cfb4780-0741-4e5a-b6f2-37ddc1fff03b">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_ed953a3b-f719-493c-8d6d-e12096077f38">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012021_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012021_2_1_0_">
                      <gml:posList srsDimension="3">329210.437 5730495.306 21.697 329213.683 5730494.951 21.697 329213.683 5730494.951 18.808 329210.437 5730495.306 18.808 329210.437 5730495.306 21.697</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_c66288f6-2605-4c6d-b6bf-c846ad8866d9">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_6113ccf8-94cf-4405-98e0-16cbb5c51e24">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012021_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012021_2_2_0_">
                      <gml:posList srsDimension="3">329213.683 5730494.951 21.697 329212.723 5730487.964 21.697 329212.723 5730487.964 18.808 329213.683 5730494.951 18.808 329213.683 5730494.951 21.697</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_35b1d8e8-d38e-4297-92a4-095ff24334d9">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_d7a4e1a5-d236-4417-9e2a-704a10935f33">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012021_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012021_2_3_0_">
                      <gml:posList srsDimension="3">329212.723 5730487.964 21.697 329209.495 5730488.348 21.697 329209.495 5730488.348 18.808 329212.723 5730487.964 18.808 329212.723 5730487.964 21.697</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_87ea3bf7-5788-4a2d-aedf-a6266e11b2d0">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_836298cf-58bd-4259-b689-66b5876a6580">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012021_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012021_2_4_0_">
                      <gml:posList srsDimension="3">329209.495 5730488.348 21.697 329210.437 5730495.306 21.697 329210.437 5730495.306 18.808 329209.495 5730488.348 18.808 329209.495 5730488.348 21.697</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_08d8e8eb-c057-4bce-ab51-dec6ef27d7cb">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_6385b571-146b-40b5-a31b-28f001ac32ed">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012021_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012021_2_5_0_">
                      <gml:posList srsDimension="3">329209.495 5730488.348 21.697 329212.723 5730487.964 21.697 329213.683 5730494.951 21.697 329210.437 5730495.306 21.697 329209.495 5730488.348 21.697</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_83d30c47-a7a4-4c62-a21b-791773860be0">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_27fa5110-2858-4bfc-8031-4c8ad97940ed">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012021_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012021_2_0_0_">
                      <gml:posList srsDimension="3">329210.437 5730495.306 18.808 329213.683 5730494.951 18.808 329212.723 5730487.964 18.808 329209.495 5730488.348 18.808 329210.437 5730495.306 18.808</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_05636231-0d30-4f28-9ec7-a2a6e3a6b9b5">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0002la7T">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0002la7T</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2723</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.196</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012013_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012013_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012013_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012013_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012013_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012013_2_0"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329144.587 5730745.329 21.925 329144.721 5730745.721 21.914 329144.817 5730746.0 21.92 329145.0 5730746.535 21.909 329145.159 5730747.0 21.895 329145.242 5730747.242 21.898 329145.502 5730748.0 21.885 329145.764 5730748.764 21.903 329145.845 5730749.0 21.905 329145.997 5730749.445 21.91</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329141.37 5730746.431 21.922 329141.415 5730746.415 21.924 329142.0 5730746.215 21.93 329142.16 5730746.16 21.928 329142.628 5730746.0 21.93 329142.905 5730745.905 21.923 329143.0 5730745.873 21.929 329143.65 5730745.65 21.92 329144.0 5730745.53 21.911 329144.395 5730745.395 21.908 329144.587 5730745.329 21.925</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329141.37 5730746.431 21.922 329141.565 5730747.0 21.917 329141.859 5730747.859 21.883 329141.907 5730748.0 21.877 329142.0 5730748.27 21.888 329142.25 5730749.0 21.915 329142.38 5730749.38 21.914 329142.593 5730750.0 21.908 329142.78 5730750.547 21.897</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329142.78 5730750.547 21.897 329143.0 5730750.472 21.906 329143.351 5730750.351 21.916 329144.0 5730750.129 21.919 329144.096 5730750.096 21.916 329144.377 5730750.0 21.909 329144.841 5730749.841 21.89 329145.0 5730749.787 21.888 329145.586 5730749.586 21.898 329145.997 5730749.445 21.91</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_4c92c927-8157-496b-88ee-6a45956723a0">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_ca57014a-3afe-437c-8353-93aeb277115a">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012013_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012013_2_1_0_">
                      <gml:posList srsDimension="3">329145.997 5730749.445 24.073 329144.587 5730745.329 24.073 329144.587 5730745.329 21.877 329145.997 5730749.445 21.877 329145.997 5730749.445 24.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_5e0ce02f-aeee-4a04-ad37-6efb191a3251">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_4360d564-2b2e-40d6-8ae6-f2dd8beb529e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012013_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012013_2_2_0_">
                      <gml:posList srsDimension="3">329144.587 5730745.329 24.073 329141.37 5730746.431 24.073 329141.37 5730746.431 21.877 329144.587 5730745.329 21.877 329144.587 5730745.329 24.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_3dae89df-af74-456c-8075-1572169e2400">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_a61e4ce7-6e04-44c0-8fdb-d34030e9718d">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012013_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012013_2_3_0_">
                      <gml:posList srsDimension="3">329141.37 5730746.431 24.073 329142.78 5730750.547 24.073 329142.78 5730750.547 21.877 329141.37 5730746.431 21.877 329141.37 5730746.431 24.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_36653ee3-1ffb-48eb-b633-d919f2dceb12">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_60e7e117-8b44-403b-a4fc-91f7408e9b27">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012013_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012013_2_4_0_">
                      <gml:posList srsDimension="3">329142.78 5730750.547 24.073 329145.997 5730749.445 24.073 329145.997 5730749.445 21.877 329142.78 5730750.547 21.877 329142.78 5730750.547 24.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_6de3f4a7-4a11-4980-85ad-d8abebdad9e7">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_fcdc7463-0eae-42e1-8940-4547ffa48f37">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012013_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012013_2_5_0_">
                      <gml:posList srsDimension="3">329142.78 5730750.547 24.073 329141.37 5730746.431 24.073 329144.587 5730745.329 24.073 329145.997 5730749.445 24.073 329142.78 5730750.547 24.073</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_151e5c9b-329f-4ac4-80fa-846deb4410b8">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_b8830274-833c-431f-af93-3a9b2bd70e5e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012013_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012013_2_0_0_">
                      <gml:posList srsDimension="3">329145.997 5730749.445 21.877 329144.587 5730745.329 21.877 329141.37 5730746.431 21.877 329142.78 5730750.547 21.877 329145.997 5730749.445 21.877</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0002la7J">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0002la7J</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2523</bldg:function>
      <bldg:roofType>9999</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">4.755</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#UUID_3de4417d-71bf-4d4a-9512-e625b45ae846"/>
              <gml:surfaceMember xlink:href="#UUID_a73656b5-ed05-47d2-aa62-3f057204f8ed"/>
              <gml:surfaceMember xlink:href="#UUID_f06a7f95-04c2-41ef-894c-e6f9bf73e22e"/>
              <gml:surfaceMember xlink:href="#UUID_533697b5-2773-476d-8ae9-6952ca2a5b30"/>
              <gml:surfaceMember xlink:href="#UUID_c459b836-ab8a-4c13-af71-8e89d96c2edf"/>
              <gml:surfaceMember xlink:href="#UUID_091afd77-e31c-414c-9486-b968aeec9f59"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329303.809 5730926.586 21.523 329304.0 5730926.764 21.529 329304.253 5730927.0 21.538 329305.0 5730927.696 21.541 329305.327 5730928.0 21.562 329306.0 5730928.627 21.594 329306.4 5730929.0 21.604 329306.735 5730929.312 21.603</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329301.038 5730929.56 21.302 329301.29 5730929.29 21.3 329301.56 5730929.0 21.314 329301.772 5730928.772 21.319 329302.0 5730928.528 21.338 329302.254 5730928.254 21.35 329302.492 5730928.0 21.395 329302.737 5730927.737 21.417 329303.0 5730927.454 21.442 329303.219 5730927.219 21.451 329303.423 5730927.0 21.485 329303.701 5730926.701 21.511 329303.809 5730926.586 21.523</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329301.038 5730929.56 21.302 329301.51 5730930.0 21.27 329302.0 5730930.456 21.264 329302.584 5730931.0 21.268 329303.0 5730931.388 21.268 329303.657 5730932.0 21.3 329303.964 5730932.286 21.306</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329303.964 5730932.286 21.306 329304.0 5730932.247 21.308 329304.119 5730932.119 21.309 329304.23 5730932.0 21.303 329304.602 5730931.602 21.276 329305.0 5730931.174 21.23 329305.084 5730931.084 21.224 329305.162 5730931.0 21.223 329305.566 5730930.566 21.24 329306.0 5730930.101 21.33 329306.049 5730930.049 21.344 329306.094 5730930.0 21.36 329306.531 5730929.531 21.555 329306.735 5730929.312 21.603</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:RoofSurface>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="UUID_c459b836-ab8a-4c13-af71-8e89d96c2edf">
                  <gml:exterior>
                    <gml:LinearRing gml:id="UUID_c459b836-ab8a-4c13-af71-8e89d96c2edf_0_">
                      <gml:posList srsDimension="3">329303.964 5730932.286 25.978 329301.038 5730929.56 25.978 329303.809 5730926.586 25.978 329306.735 5730929.312 25.978 329303.964 5730932.286 25.978</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="UUID_a73656b5-ed05-47d2-aa62-3f057204f8ed">
                  <gml:exterior>
                    <gml:LinearRing gml:id="UUID_a73656b5-ed05-47d2-aa62-3f057204f8ed_0_">
                      <gml:posList srsDimension="3">329306.735 5730929.312 25.978 329303.809 5730926.586 25.978 329303.809 5730926.586 21.223 329306.735 5730929.312 21.223 329306.735 5730929.312 25.978</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="UUID_3de4417d-71bf-4d4a-9512-e625b45ae846">
                  <gml:exterior>
                    <gml:LinearRing gml:id="UUID_3de4417d-71bf-4d4a-9512-e625b45ae846_0_">
                      <gml:posList srsDimension="3">329303.809 5730926.586 25.978 329301.038 5730929.56 25.978 329301.038 5730929.56 21.223 329303.809 5730926.586 21.223 329303.809 5730926.586 25.978</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="UUID_f06a7f95-04c2-41ef-894c-e6f9bf73e22e">
                  <gml:exterior>
                    <gml:LinearRing gml:id="UUID_f06a7f95-04c2-41ef-894c-e6f9bf73e22e_0_">
                      <gml:posList srsDimension="3">329301.038 5730929.56 25.978 329303.964 5730932.286 25.978 329303.964 5730932.286 21.223 329301.038 5730929.56 21.223 329301.038 5730929.56 25.978</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="UUID_533697b5-2773-476d-8ae9-6952ca2a5b30">
                  <gml:exterior>
                    <gml:LinearRing gml:id="UUID_533697b5-2773-476d-8ae9-6952ca2a5b30_0_">
                      <gml:posList srsDimension="3">329303.964 5730932.286 25.978 329306.735 5730929.312 25.978 329306.735 5730929.312 21.223 329303.964 5730932.286 21.223 329303.964 5730932.286 25.978</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface>
              <gml:surfaceMember>
                <gml:Polygon gml:id="UUID_091afd77-e31c-414c-9486-b968aeec9f59">
                  <gml:exterior>
                    <gml:LinearRing gml:id="UUID_091afd77-e31c-414c-9486-b968aeec9f59_0_">
                      <gml:posList srsDimension="3">329306.735 5730929.312 21.223 329303.809 5730926.586 21.223 329301.038 5730929.56 21.223 329303.964 5730932.286 21.223 329306.735 5730929.312 21.223</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000rD7T">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000rD7T</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="UUID_3e7f23b8-e58e-4de4-a8be-daff7bc6504e">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>3100</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">7.653</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_4"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_6"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_7"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_5"/>
                  <gml:surfaceMember xlink:href="#UUID_b2c74c29-9e4a-47d5-b817-f0c056930d54"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_9"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_8"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_1"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_2"/>
                  <gml:surfaceMember xlink:href="#UUID_b0176a6b-6ff1-43d2-b55f-7896eb8c2c0b"/>
                  <gml:surfaceMember xlink:href="#UUID_f389f9c7-21f2-460f-8d57-928c001af31b"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012015_2_0"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329284.069 5730969.038 21.378 329284.128 5730969.128 21.372 329284.698 5730970.0 21.317 329285.0 5730970.461 21.315 329285.352 5730971.0 21.306 329286.0 5730971.99 21.28 329286.007 5730972.0 21.28 329286.019 5730972.019 21.279 329286.661 5730973.0 21.22 329287.0 5730973.518 21.194 329287.315 5730974.0 21.167 329287.911 5730974.911 21.116 329287.969 5730975.0 21.111 329288.0 5730975.047 21.109 329288.247 5730975.425 21.099</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329288.247 5730975.425 21.099 329288.623 5730976.0 21.084 329289.0 5730976.576 21.074 329289.278 5730977.0 21.073 329289.803 5730977.803 21.078 329289.932 5730978.0 21.08 329290.0 5730978.104 21.08 329290.586 5730979.0 21.074 329291.0 5730979.633 21.076 329291.24 5730980.0 21.078 329291.694 5730980.694 21.073 329291.894 5730981.0 21.071 329292.0 5730981.162 21.07 329292.425 5730981.812 21.079</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329292.425 5730981.812 21.079 329292.659 5730981.659 21.083 329293.0 5730981.435 21.073 329293.263 5730981.263 21.065 329293.664 5730981.0 21.053 329293.867 5730980.867 21.053 329294.0 5730980.78 21.05 329294.471 5730980.471 21.055 329295.0 5730980.124 21.051 329295.075 5730980.075 21.05 329295.19 5730980.0 21.05 329295.679 5730979.679 21.053 329296.0 5730979.469 21.05 329296.283 5730979.283 21.047 329296.694 5730979.014 21.057</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.694 5730979.014 21.057 329296.715 5730979.0 21.057 329296.887 5730978.887 21.061 329297.0 5730978.813 21.06 329297.491 5730978.491 21.055 329298.0 5730978.158 21.058 329298.095 5730978.095 21.059 329298.241 5730978.0 21.058 329298.7 5730977.7 21.056 329299.0 5730977.503 21.06 329299.304 5730977.304 21.061 329299.767 5730977.0 21.055 329299.908 5730976.908 21.053 329300.0 5730976.847 21.053 329300.512 5730976.512 21.05 329301.0 5730976.192 21.046 329301.116 5730976.116 21.048 329301.293 5730976.0 21.044 329301.72 5730975.72 21.041 329302.0 5730975.536 21.039 329302.324 5730975.324 21.044 329302.819 5730975.0 21.042 329302.928 5730974.928 21.042 329303.0 5730974.881 21.042 329303.532 5730974.532 21.049 329304.0 5730974.226 21.048 329304.136 5730974.136 21.05 329304.344 5730974.0 21.05 329304.445 5730973.934 21.051</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329300.252 5730967.538 21.143 329300.556 5730968.0 21.12 329301.0 5730968.678 21.113 329301.211 5730969.0 21.106 329301.613 5730969.613 21.098 329301.867 5730970.0 21.095 329302.0 5730970.204 21.09 329302.522 5730971.0 21.074 329303.0 5730971.729 21.082 329303.177 5730972.0 21.085 329303.515 5730972.515 21.075 329303.833 5730973.0 21.062 329304.0 5730973.255 21.057 329304.445 5730973.934 21.051</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.06 5730961.141 21.236 329296.623 5730962.0 21.205 329297.0 5730962.575 21.219 329297.278 5730963.0 21.232 329297.808 5730963.808 21.224 329297.934 5730964.0 21.221 329298.0 5730964.101 21.218 329298.589 5730965.0 21.176 329299.0 5730965.627 21.173 329299.245 5730966.0 21.173 329299.71 5730966.71 21.173 329299.9 5730967.0 21.169 329300.0 5730967.152 21.162 329300.252 5730967.538 21.143</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329284.069 5730969.038 21.378 329284.127 5730969.0 21.38 329284.653 5730968.653 21.37 329285.0 5730968.425 21.368 329285.256 5730968.256 21.36 329285.645 5730968.0 21.354 329285.859 5730967.859 21.346 329286.0 5730967.766 21.338 329286.462 5730967.462 21.328 329287.0 5730967.108 21.422 329287.065 5730967.065 21.424 329287.164 5730967.0 21.419 329287.668 5730966.668 21.34 329288.0 5730966.449 21.354 329288.271 5730966.271 21.345 329288.682 5730966.0 21.357 329288.874 5730965.874 21.351 329289.0 5730965.791 21.356 329289.477 5730965.477 21.354 329290.0 5730965.132 21.387 329290.08 5730965.08 21.384 329290.2 5730965.0 21.382 329290.683 5730964.683 21.334 329291.0 5730964.473 21.329 329291.285 5730964.285 21.313 329291.719 5730964.0 21.332 329291.888 5730963.888 21.334 329292.0 5730963.815 21.329 329292.491 5730963.491 21.3 329293.0 5730963.156 21.354 329293.094 5730963.094 21.354 329293.237 5730963.0 21.348 329293.697 5730962.697 21.295 329294.0 5730962.498 21.31 329294.3 5730962.3 21.304 329294.756 5730962.0 21.31 329294.903 5730961.903 21.304 329295.0 5730961.839 21.3 329295.506 5730961.506 21.24 329296.0 5730961.181 21.238 329296.06 5730961.141 21.236</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_312b1f29-e546-4607-b344-6e4b60bf5e8e">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_6997fb9e-e680-4d87-abd1-9e6f86208af1">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_1">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_1_0_">
                          <gml:posList srsDimension="3">329284.069 5730969.038 24.49 329288.247 5730975.425 28.653 329288.247 5730975.425 21.0 329284.069 5730969.038 21.0 329284.069 5730969.038 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_7a66cd66-8574-4344-a478-183c741e8f8e">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_9efb7e3f-46d1-4384-a12b-510f679b8cf0">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_2">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_2_0_">
                          <gml:posList srsDimension="3">329288.247 5730975.425 28.653 329292.425 5730981.812 24.49 329292.425 5730981.812 21.0 329288.247 5730975.425 21.0 329288.247 5730975.425 28.653</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_a4d8e035-e17a-4144-b04b-216ec26d5bca">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_277c361e-e367-43dc-be17-cb4a0cdd97a9">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_4">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_4_0_">
                          <gml:posList srsDimension="3">329296.694 5730979.014 24.49 329304.445 5730973.934 24.49 329304.445 5730973.934 21.0 329296.694 5730979.014 21.0 329296.694 5730979.014 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_fd341a5b-0afb-4a03-9f60-f6c7b1438c39">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_fb53c738-69b3-4831-a49e-fc5a6d29eed4">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_5">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_5_0_">
                          <gml:posList srsDimension="3">329304.445 5730973.934 24.49 329300.252 5730967.538 28.653 329300.252 5730967.538 21.0 329304.445 5730973.934 21.0 329304.445 5730973.934 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_092182c9-cfb2-48de-b333-1199adecbf90">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_5266d284-e296-4dc9-9580-8f9ab1f27b5f">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_6">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_6_0_">
                          <gml:posList srsDimension="3">329300.252 5730967.538 28.653 329296.06 5730961.141 24.49 329296.06 5730961.141 21.0 329300.252 5730967.538 21.0 329300.252 5730967.538 28.653</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_bdaed006-1ef6-44e4-97ed-23fbbfdb2820">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_9ce88359-5d96-459a-be64-12649dd9bd81">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_7">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_7_0_">
                          <gml:posList srsDimension="3">329296.06 5730961.141 24.49 329284.069 5730969.038 24.49 329284.069 5730969.038 21.0 329296.06 5730961.141 21.0 329296.06 5730961.141 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_36f41813-70f4-4744-ab33-d0895386ef7b">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_62de54a5-1d49-4794-b861-d5d272af7cf2">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_8">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_8_0_">
                          <gml:posList srsDimension="3">329288.247 5730975.425 28.653 329284.069 5730969.038 24.49 329296.06 5730961.141 24.49 329300.252 5730967.538 28.653 329288.247 5730975.425 28.653</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_80ee3932-0819-4982-b476-b629b1963995">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_1039fe1b-886b-4a66-8b67-cd5c01bed448">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_9">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_9_0_">
                          <gml:posList srsDimension="3">329300.252 5730967.538 28.653 329304.445 5730973.934 24.49 329296.694 5730979.014 24.49 329292.425 5730981.812 24.49 329288.247 5730975.425 28.653 329300.252 5730967.538 28.653</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_cc92981e-4e46-4eea-81bc-03c439b46c41">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_114d5247-a0d7-4ebb-bd7c-ee5bfe7206aa">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012015_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012015_2_0_0_">
                          <gml:posList srsDimension="3">329284.069 5730969.038 21.0 329288.247 5730975.425 21.0 329292.425 5730981.812 21.0 329296.694 5730979.014 21.0 329304.445 5730973.934 21.0 329300.252 5730967.538 21.0 329296.06 5730961.141 21.0 329284.069 5730969.038 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_7fb16bfd-6f37-469e-a260-c01d07bd537a">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_f389f9c7-21f2-460f-8d57-928c001af31b">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329296.694 5730979.014 24.102 329296.279 5730979.286 24.49 329296.694 5730979.014 24.49 329296.694 5730979.014 24.102</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_b2c74c29-9e4a-47d5-b817-f0c056930d54">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329296.694 5730979.014 24.102 329296.694 5730979.014 21.0 329296.279 5730979.286 21.0 329296.279 5730979.286 24.49 329296.694 5730979.014 24.102</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_b0176a6b-6ff1-43d2-b55f-7896eb8c2c0b">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329292.425 5730981.812 21.0 329292.425 5730981.812 24.49 329296.279 5730979.286 24.49 329296.279 5730979.286 21.0 329292.425 5730981.812 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="GUID_1543405942858_111012016">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>5000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">5.31</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_15"/>
                  <gml:surfaceMember xlink:href="#UUID_35c6b97b-8702-433e-a33d-d1ec161b2dcb"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_2"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_16"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_0"/>
                  <gml:surfaceMember xlink:href="#UUID_8c649c2b-682b-4cd3-8e80-23f8b4132753"/>
                  <gml:surfaceMember xlink:href="#UUID_d5ff12d7-59fa-4eb6-acf7-dc41065cff9b"/>
                  <gml:surfaceMember xlink:href="#UUID_05f3e4db-73c8-469e-803d-2022fd61d251"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_17"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_13"/>
                  <gml:surfaceMember xlink:href="#UUID_45678d3a-31da-41d7-9751-91da6991ee8f"/>
                  <gml:surfaceMember xlink:href="#UUID_fc42ad10-1246-45ee-beb9-40f8468ec915"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_6"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_7"/>
                  <gml:surfaceMember xlink:href="#UUID_9fc8add9-2e33-453e-a222-8dc301f9dfa0"/>
                  <gml:surfaceMember xlink:href="#UUID_db5abe15-4925-4d6c-a4c8-61c1697fce39"/>
                  <gml:surfaceMember xlink:href="#UUID_c13bcdaa-de45-4f71-9e24-55e42064d8b8"/>
                  <gml:surfaceMember xlink:href="#UUID_c5880e96-60db-4217-a855-648d03f6e2f7"/>
                  <gml:surfaceMember xlink:href="#UUID_4cc65edd-6340-4072-8f59-bbbb2b3dbfec"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_9"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_8"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_3"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012016_2_10"/>
                  <gml:surfaceMember xlink:href="#UUID_88d61d06-0e80-4d94-9417-2030f276dca5"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.261 5730983.774 21.043 329299.57 5730983.57 21.036 329299.67 5730983.503 21.038</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329297.092 5730979.614 21.049 329297.348 5730980.0 21.043 329298.0 5730980.984 21.03 329298.011 5730981.0 21.03 329298.032 5730981.032 21.03 329298.674 5730982.0 21.037 329299.0 5730982.492 21.03 329299.337 5730983.0 21.037 329299.67 5730983.503 21.038</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.694 5730979.014 21.057 329297.0 5730979.476 21.05 329297.092 5730979.614 21.049</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.279 5730979.286 21.047 329296.283 5730979.283 21.047 329296.694 5730979.014 21.057</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329292.425 5730981.812 21.079 329292.659 5730981.659 21.083 329293.0 5730981.435 21.073 329293.263 5730981.263 21.065 329293.664 5730981.0 21.053 329293.867 5730980.867 21.053 329294.0 5730980.78 21.05 329294.471 5730980.471 21.055 329295.0 5730980.124 21.051 329295.075 5730980.075 21.05 329295.19 5730980.0 21.05 329295.679 5730979.679 21.053 329296.0 5730979.469 21.05 329296.279 5730979.286 21.047</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329292.425 5730981.812 21.079 329292.548 5730982.0 21.081 329293.0 5730982.69 21.104 329293.203 5730983.0 21.11 329293.586 5730983.586 21.133 329293.857 5730984.0 21.144 329294.0 5730984.219 21.159 329294.282 5730984.65 21.162</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329294.282 5730984.65 21.162 329294.511 5730985.0 21.164 329295.0 5730985.748 21.14 329295.165 5730986.0 21.135 329295.478 5730986.478 21.14 329295.819 5730987.0 21.144 329295.837 5730987.027 21.143</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329295.837 5730987.027 21.143 329295.934 5730987.176 21.14</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329295.934 5730987.176 21.14 329296.0 5730987.134 21.139 329296.083 5730987.083 21.138 329296.214 5730987.0 21.136 329296.696 5730986.696 21.117 329296.88 5730986.581 21.116</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.864 5730986.557 21.116 329296.88 5730986.581 21.116</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.864 5730986.557 21.116 329297.0 5730986.466 21.115 329297.279 5730986.279 21.107 329297.698 5730986.0 21.096 329297.87 5730985.885 21.09</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329297.87 5730985.885 21.09 329297.879 5730985.879 21.09 329298.0 5730985.798 21.088 329298.479 5730985.479 21.085 329299.0 5730985.131 21.073 329299.078 5730985.078 21.07 329299.196 5730985.0 21.068 329299.678 5730984.678 21.057 329299.805 5730984.593 21.054</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.756 5730984.519 21.053 329299.805 5730984.593 21.054</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.261 5730983.774 21.043 329299.411 5730984.0 21.046 329299.756 5730984.519 21.053</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_d247e006-aedb-44dc-bcd3-593576a75f59">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_23fc9b73-ae03-44b7-9d4b-72dc4d2951f2">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_2">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_2_0_">
                          <gml:posList srsDimension="3">329299.67 5730983.503 24.106 329297.092 5730979.614 24.102 329297.092 5730979.614 21.0 329299.67 5730983.503 21.0 329299.67 5730983.503 24.106</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_b9e20d15-df24-46a3-b759-6cb53f9b9daf">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_c243b10c-ece8-4668-8084-d1613cc9404a">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_3">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_3_0_">
                          <gml:posList srsDimension="3">329297.092 5730979.614 24.102 329296.694 5730979.014 24.102 329296.694 5730979.014 21.0 329297.092 5730979.614 21.0 329297.092 5730979.614 24.102</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_42e67ec2-66b0-428d-9eca-4501bfc4cdc3">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_8b63f0fa-e25f-4175-831c-02fc60aeadd5">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_6">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_6_0_">
                          <gml:posList srsDimension="3">329292.425 5730981.812 24.49 329294.282 5730984.65 24.49 329294.282 5730984.65 21.0 329292.425 5730981.812 21.0 329292.425 5730981.812 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_fcaec7d2-6dec-47fb-9093-3cc02d2b0ce1">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_2b411c8e-d06f-4486-93f1-0d6c7e503f11">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_7">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_7_0_">
                          <gml:posList srsDimension="3">329294.282 5730984.65 24.49 329295.837 5730987.027 24.49 329295.837 5730987.027 21.0 329294.282 5730984.65 21.0 329294.282 5730984.65 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_9f311507-4db8-426a-a0e4-5b024f61e28a">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_a9f1b517-f384-45a1-8896-a3c5d3d85a0a">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_8">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_8_0_">
                          <gml:posList srsDimension="3">329295.837 5730987.027 24.49 329295.934 5730987.176 24.49 329295.934 5730987.176 21.0 329295.837 5730987.027 21.0 329295.837 5730987.027 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_79f6d246-35fc-4ee8-96b9-29485283d1f2">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_4dc571d3-ef67-4c55-aab4-1972507f9d6d">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_9">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_9_0_">
                          <gml:posList srsDimension="3">329295.934 5730987.176 24.49 329296.88 5730986.581 25.364 329296.88 5730986.581 21.0 329295.934 5730987.176 21.0 329295.934 5730987.176 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_28da411a-149c-4520-a5e2-6dc9e870eea7">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_64a5b846-486c-4e8a-ab4b-e00939f44599">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_10">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_10_0_">
                          <gml:posList srsDimension="3">329296.88 5730986.581 25.364 329296.864 5730986.557 25.364 329296.864 5730986.557 21.0 329296.88 5730986.581 21.0 329296.88 5730986.581 25.364</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_8b612237-49cf-4f58-be3c-5927708be7d3">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_41f8001c-955b-4333-94f9-d26906cbcb60">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_13">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_13_0_">
                          <gml:posList srsDimension="3">329299.805 5730984.593 24.49 329299.756 5730984.519 24.49 329299.756 5730984.519 21.0 329299.805 5730984.593 21.0 329299.805 5730984.593 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_54528064-afec-4132-b8c9-a7df591db557">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_19c19676-d02d-46ce-a448-83b7ae89e6f3">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_15">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_15_0_">
                          <gml:posList srsDimension="3">329296.88 5730986.581 25.364 329295.934 5730987.176 24.49 329295.837 5730987.027 24.49 329294.282 5730984.65 24.49 329292.425 5730981.812 24.49 329292.519 5730977.768 26.31 329297.87 5730985.885 26.31 329296.864 5730986.557 25.364 329296.88 5730986.581 25.364</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_8402d781-92bb-4ae2-9961-a224829c4de3">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_e5a9e1ce-8f39-4268-87d4-e4378c2bb7b3">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_16">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_16_0_">
                          <gml:posList srsDimension="3">329292.519 5730977.768 26.31 329292.425 5730981.812 24.49 329296.279 5730979.286 24.49 329292.519 5730977.768 26.31</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_ffaa4652-c169-428e-97d0-d3cb06f00e13">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_24365431-7b80-4ccd-b4ac-ac17ecbaac62">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_17">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_17_0_">
                          <gml:posList srsDimension="3">329292.519 5730977.768 26.31 329296.279 5730979.286 24.49 329296.694 5730979.014 24.102 329297.092 5730979.614 24.102 329299.67 5730983.503 24.106 329299.261 5730983.774 24.49 329299.756 5730984.519 24.49 329299.805 5730984.593 24.49 329297.87 5730985.885 26.31 329292.519 5730977.768 26.31</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_c5890a4a-eaa8-4492-a735-a494c9a0e446">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_51290f82-3381-4f50-a1de-df094fc0408d">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012016_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012016_2_0_0_">
                          <gml:posList srsDimension="3">329299.261 5730983.774 21.0 329299.67 5730983.503 21.0 329297.092 5730979.614 21.0 329296.694 5730979.014 21.0 329296.279 5730979.286 21.0 329292.425 5730981.812 21.0 329294.282 5730984.65 21.0 329295.837 5730987.027 21.0 329295.934 5730987.176 21.0 329296.88 5730986.581 21.0 329296.864 5730986.557 21.0 329297.87 5730985.885 21.0 329299.805 5730984.593 21.0 329299.756 5730984.519 21.0 329299.261 5730983.774 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_acb3ee39-1cea-4215-91ce-fb76a3f7e388">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_45678d3a-31da-41d7-9751-91da6991ee8f">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.261 5730983.774 21.0 329299.261 5730983.774 21.036 329299.67 5730983.503 21.036 329299.67 5730983.503 21.0 329299.261 5730983.774 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_d5ff12d7-59fa-4eb6-acf7-dc41065cff9b">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.261 5730983.774 24.232 329299.261 5730983.774 24.49 329299.536 5730983.592 24.232 329299.261 5730983.774 24.232</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_8c649c2b-682b-4cd3-8e80-23f8b4132753">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.261 5730983.774 21.036 329299.261 5730983.774 24.232 329299.536 5730983.592 24.232 329299.67 5730983.503 24.106 329299.67 5730983.503 21.036 329299.261 5730983.774 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_35c6b97b-8702-433e-a33d-d1ec161b2dcb">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329296.694 5730979.014 21.0 329296.694 5730979.014 24.102 329296.279 5730979.286 24.49 329296.279 5730979.286 21.0 329296.694 5730979.014 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_88d61d06-0e80-4d94-9417-2030f276dca5">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329296.279 5730979.286 24.49 329292.425 5730981.812 24.49 329292.425 5730981.812 21.0 329296.279 5730979.286 21.0 329296.279 5730979.286 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_a00b9b89-e143-4a1a-9be6-9802dc8e5eb4">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_c5880e96-60db-4217-a855-648d03f6e2f7">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329296.864 5730986.557 24.658 329296.864 5730986.557 25.364 329297.87 5730985.885 26.31 329297.87 5730985.885 24.658 329296.864 5730986.557 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_fc42ad10-1246-45ee-beb9-40f8468ec915">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329296.864 5730986.557 24.658 329297.87 5730985.885 24.658 329297.87 5730985.885 21.0 329296.864 5730986.557 21.0 329296.864 5730986.557 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_6606ab61-6b6d-4708-806b-2d23c60a075c">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_4cc65edd-6340-4072-8f59-bbbb2b3dbfec">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329297.87 5730985.885 24.658 329297.87 5730985.885 26.31 329299.626 5730984.712 24.658 329297.87 5730985.885 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_9fc8add9-2e33-453e-a222-8dc301f9dfa0">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.805 5730984.593 24.49 329299.805 5730984.593 21.0 329297.87 5730985.885 21.0 329297.87 5730985.885 24.658 329299.626 5730984.712 24.658 329299.805 5730984.593 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_aa675e7a-4274-4eb4-bf96-bb14381c3cfc">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_db5abe15-4925-4d6c-a4c8-61c1697fce39">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.756 5730984.519 21.0 329299.756 5730984.519 21.036 329299.261 5730983.774 21.036 329299.261 5730983.774 21.0 329299.756 5730984.519 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_05f3e4db-73c8-469e-803d-2022fd61d251">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.756 5730984.519 24.232 329299.756 5730984.519 24.49 329299.261 5730983.774 24.49 329299.261 5730983.774 24.232 329299.756 5730984.519 24.232</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_c13bcdaa-de45-4f71-9e24-55e42064d8b8">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.756 5730984.519 21.036 329299.756 5730984.519 24.232 329299.261 5730983.774 24.232 329299.261 5730983.774 21.036 329299.756 5730984.519 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="GUID_1543405942858_111012017">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>3100</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">8.831</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#UUID_d5101a56-2013-4720-b5f9-b1a3f49f569a"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_11"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_4"/>
                  <gml:surfaceMember xlink:href="#UUID_ce3fb47d-96f6-4459-a6b1-8d2f31fbfee0"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_6"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_5"/>
                  <gml:surfaceMember xlink:href="#UUID_66507e05-cef9-4e1e-89b0-b58070971e3e"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_10"/>
                  <gml:surfaceMember xlink:href="#UUID_94fb3fbc-ab8a-4253-95b4-3817bac73366"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_7"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_15"/>
                  <gml:surfaceMember xlink:href="#UUID_e3c84657-9135-4841-8239-0a87a42bfc0b"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_12"/>
                  <gml:surfaceMember xlink:href="#UUID_ddd664cc-a2cd-4f34-9876-6c348a5a9a1e"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_3"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_0"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_9"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_14"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012017_2_1"/>
                  <gml:surfaceMember xlink:href="#UUID_cf892607-3d57-4fd0-afc4-31b5165b7d1e"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.756 5730984.519 21.053 329299.805 5730984.593 21.054</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.864 5730986.557 21.116 329297.0 5730986.466 21.115 329297.279 5730986.279 21.107 329297.698 5730986.0 21.096 329297.879 5730985.879 21.09 329298.0 5730985.798 21.088 329298.479 5730985.479 21.085 329299.0 5730985.131 21.073 329299.078 5730985.078 21.07 329299.196 5730985.0 21.068 329299.678 5730984.678 21.057 329299.805 5730984.593 21.054</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.864 5730986.557 21.116 329296.88 5730986.581 21.116</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329296.88 5730986.581 21.116 329297.0 5730986.762 21.118 329297.157 5730987.0 21.117 329297.465 5730987.465 21.111 329297.819 5730988.0 21.104 329298.0 5730988.273 21.1 329298.481 5730989.0 21.095 329299.0 5730989.784 21.09 329299.143 5730990.0 21.087 329299.423 5730990.423 21.082 329299.805 5730991.0 21.074 329300.0 5730991.295 21.07 329300.286 5730991.728 21.067</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329300.286 5730991.728 21.067 329300.467 5730992.0 21.065 329301.0 5730992.806 21.06 329301.128 5730993.0 21.059 329301.38 5730993.38 21.056 329301.79 5730994.0 21.052 329302.0 5730994.317 21.047 329302.452 5730995.0 21.04 329303.0 5730995.828 21.04 329303.114 5730996.0 21.04 329303.337 5730996.337 21.037 329303.709 5730996.899 21.031</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329303.709 5730996.899 21.031 329303.824 5730996.824 21.032 329304.0 5730996.708 21.033 329304.428 5730996.428 21.036 329305.0 5730996.053 21.03 329305.032 5730996.032 21.029 329305.081 5730996.0 21.028 329305.636 5730995.636 21.017 329306.0 5730995.398 21.016 329306.24 5730995.24 21.018 329306.607 5730995.0 21.014 329306.844 5730994.844 21.012 329307.0 5730994.743 21.01 329307.449 5730994.449 21.006 329308.0 5730994.087 21.0 329308.053 5730994.053 21.001 329308.133 5730994.0 21.0 329308.657 5730993.657 21.003 329309.0 5730993.432 21.011 329309.139 5730993.341 21.017</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329309.139 5730993.341 21.017 329309.151 5730993.359 21.017</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329309.151 5730993.359 21.017 329309.277 5730993.277 21.023 329309.704 5730993.0 21.027 329309.883 5730992.883 21.029 329310.0 5730992.807 21.032 329310.489 5730992.489 21.045 329311.0 5730992.157 21.05 329311.095 5730992.095 21.051 329311.241 5730992.0 21.055 329311.701 5730991.701 21.067 329312.0 5730991.506 21.07 329312.307 5730991.307 21.073 329312.778 5730991.0 21.086 329312.913 5730990.913 21.09 329313.0 5730990.856 21.091 329313.519 5730990.519 21.095 329314.0 5730990.205 21.098 329314.125 5730990.125 21.098 329314.316 5730990.0 21.1 329314.73 5730989.73 21.103 329314.791 5730989.691 21.098</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329314.791 5730989.691 21.098 329314.885 5730989.629 21.091</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329311.443 5730984.376 21.055 329311.57 5730984.57 21.053 329311.852 5730985.0 21.047 329312.0 5730985.226 21.054 329312.507 5730986.0 21.075 329313.0 5730986.752 21.118 329313.162 5730987.0 21.125 329313.471 5730987.471 21.112 329313.818 5730988.0 21.087 329314.0 5730988.278 21.088 329314.473 5730989.0 21.086 329314.885 5730989.629 21.091</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329308.001 5730979.123 21.022 329308.576 5730980.0 21.034 329309.0 5730980.648 21.043 329309.231 5730981.0 21.05 329309.67 5730981.67 21.037 329309.886 5730982.0 21.033 329310.0 5730982.174 21.033 329310.541 5730983.0 21.039 329311.0 5730983.7 21.058 329311.197 5730984.0 21.06 329311.443 5730984.376 21.055</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329300.169 5730984.255 21.043 329300.221 5730984.221 21.042 329300.558 5730984.0 21.046 329300.825 5730983.825 21.05 329301.0 5730983.71 21.044 329301.429 5730983.429 21.043 329302.0 5730983.055 21.032 329302.033 5730983.033 21.031 329302.084 5730983.0 21.033 329302.637 5730982.637 21.055 329303.0 5730982.4 21.046 329303.242 5730982.242 21.04 329303.61 5730982.0 21.042 329303.846 5730981.846 21.048 329304.0 5730981.745 21.047 329304.45 5730981.45 21.058 329305.0 5730981.089 21.089 329305.054 5730981.054 21.089 329305.136 5730981.0 21.086 329305.658 5730980.658 21.05 329306.0 5730980.434 21.037 329306.262 5730980.262 21.03 329306.663 5730980.0 21.033 329306.866 5730979.866 21.041 329307.0 5730979.779 21.038 329307.471 5730979.471 21.035 329308.0 5730979.124 21.022 329308.001 5730979.123 21.022</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.756 5730984.519 21.053 329300.0 5730984.363 21.047 329300.169 5730984.255 21.043</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_ea502987-2cb7-4f1c-9726-ceac9e4fd5fb">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_edaa8709-cce5-42e9-8f8e-51ad353accbc">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_1">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_1_0_">
                          <gml:posList srsDimension="3">329299.756 5730984.519 24.584 329299.805 5730984.593 24.658 329299.805 5730984.593 21.0 329299.756 5730984.519 21.0 329299.756 5730984.519 24.584</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_6a3d9e12-ea3a-465f-b6e0-65fc418c8c69">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_f0121bab-6715-44fa-b302-3d8553198219">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_3">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_3_0_">
                          <gml:posList srsDimension="3">329296.864 5730986.557 24.658 329296.88 5730986.581 24.683 329296.88 5730986.581 21.0 329296.864 5730986.557 21.0 329296.864 5730986.557 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_1669644a-a988-4b7e-a657-6be2a7a0fa36">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_3bb4f805-7168-442d-a84f-92f41645e0b0">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_4">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_4_0_">
                          <gml:posList srsDimension="3">329296.88 5730986.581 24.683 329300.286 5730991.728 29.831 329300.286 5730991.728 21.0 329296.88 5730986.581 21.0 329296.88 5730986.581 24.683</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_57e83f45-5a63-4dee-b1fc-31970e5f149d">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_0c79a89b-53e2-4805-8e03-308e60bc9ad2">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_5">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_5_0_">
                          <gml:posList srsDimension="3">329300.286 5730991.728 29.831 329303.709 5730996.899 24.658 329303.709 5730996.899 21.0 329300.286 5730991.728 21.0 329300.286 5730991.728 29.831</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_ddd0fea1-e87a-4f04-b705-ac12e8d55539">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_281b47d8-0eca-43b1-a5ed-c8471f655f44">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_6">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_6_0_">
                          <gml:posList srsDimension="3">329303.709 5730996.899 24.658 329309.139 5730993.341 24.676 329309.139 5730993.341 21.0 329303.709 5730996.899 21.0 329303.709 5730996.899 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_16da0c59-b2d3-4fdc-afcd-b983007086e1">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_defcca5f-d87b-42e8-88d4-3e52979bf3ab">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_7">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_7_0_">
                          <gml:posList srsDimension="3">329309.139 5730993.341 24.676 329309.151 5730993.359 24.658 329309.151 5730993.359 21.0 329309.139 5730993.341 21.0 329309.139 5730993.341 24.676</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_3730ea66-32a8-41c2-a891-66e2531cda2a">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_efcad024-1b08-4dfd-9565-cfbe3ff11553">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_9">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_9_0_">
                          <gml:posList srsDimension="3">329314.791 5730989.691 24.658 329314.885 5730989.629 24.659 329314.885 5730989.629 21.0 329314.791 5730989.691 21.0 329314.791 5730989.691 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_20e0a308-af59-4ab3-93b3-a987455855c0">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_34838c4a-5ca4-4c7c-a4cf-0edb0edeb6fd">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_10">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_10_0_">
                          <gml:posList srsDimension="3">329314.885 5730989.629 24.659 329311.443 5730984.376 29.831 329311.443 5730984.376 21.0 329314.885 5730989.629 21.0 329314.885 5730989.629 24.659</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_6ee5dc93-b9b0-4a6c-ac10-27e9a13a1684">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_3faadaa6-4a9d-44c3-9f7f-ad9ff3cacbb1">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_11">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_11_0_">
                          <gml:posList srsDimension="3">329311.443 5730984.376 29.831 329308.001 5730979.123 24.658 329308.001 5730979.123 21.0 329311.443 5730984.376 21.0 329311.443 5730984.376 29.831</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_1f233d44-d8c0-4c12-9aca-b16c5931f1e4">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_3eae6afe-c320-4fce-8150-237fa837fe8a">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_12">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_12_0_">
                          <gml:posList srsDimension="3">329308.001 5730979.123 24.658 329300.169 5730984.255 24.592 329300.169 5730984.255 21.0 329308.001 5730979.123 21.0 329308.001 5730979.123 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_8acb9721-b289-4fe5-8b8f-ca5df4d419dc">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_639f02c6-1927-4d8c-9f5a-b4598fa9887c">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_14">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_14_0_">
                          <gml:posList srsDimension="3">329300.286 5730991.728 29.831 329296.88 5730986.581 24.683 329296.864 5730986.557 24.658 329299.805 5730984.593 24.658 329299.756 5730984.519 24.584 329300.169 5730984.255 24.592 329308.001 5730979.123 24.658 329311.443 5730984.376 29.831 329300.286 5730991.728 29.831</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_20c9ff81-45e9-42a5-9cae-b696c8d21d34">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_13abe75c-f41f-4718-9c04-c67608c1a411">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_15">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_15_0_">
                          <gml:posList srsDimension="3">329311.443 5730984.376 29.831 329314.885 5730989.629 24.659 329314.791 5730989.691 24.658 329309.151 5730993.359 24.658 329309.139 5730993.341 24.676 329303.709 5730996.899 24.658 329300.286 5730991.728 29.831 329311.443 5730984.376 29.831</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_a8905664-8d49-4261-812e-e06b94285234">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_a8b1ef21-261a-4611-8ceb-73556031f2bd">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012017_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012017_2_0_0_">
                          <gml:posList srsDimension="3">329299.756 5730984.519 21.0 329299.805 5730984.593 21.0 329296.864 5730986.557 21.0 329296.88 5730986.581 21.0 329300.286 5730991.728 21.0 329303.709 5730996.899 21.0 329309.139 5730993.341 21.0 329309.151 5730993.359 21.0 329314.791 5730989.691 21.0 329314.885 5730989.629 21.0 329311.443 5730984.376 21.0 329308.001 5730979.123 21.0 329300.169 5730984.255 21.0 329299.756 5730984.519 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_0d6c1845-efbd-476b-ad6b-9738bf49a328">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_e3c84657-9135-4841-8239-0a87a42bfc0b">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.805 5730984.593 24.49 329299.805 5730984.593 24.658 329299.626 5730984.712 24.658 329299.805 5730984.593 24.49</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_ce3fb47d-96f6-4459-a6b1-8d2f31fbfee0">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329297.87 5730985.885 21.0 329297.87 5730985.885 24.658 329296.864 5730986.557 24.658 329296.864 5730986.557 21.0 329297.87 5730985.885 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_66507e05-cef9-4e1e-89b0-b58070971e3e">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.805 5730984.593 21.0 329299.805 5730984.593 24.49 329299.626 5730984.712 24.658 329297.87 5730985.885 24.658 329297.87 5730985.885 21.0 329299.805 5730984.593 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_d5101a56-2013-4720-b5f9-b1a3f49f569a">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329309.151 5730993.359 24.658 329314.791 5730989.691 24.658 329314.791 5730989.691 21.0 329309.151 5730993.359 21.0 329309.151 5730993.359 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_0dc52e8d-5cd1-4451-80b1-dfd5013973f2">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_cf892607-3d57-4fd0-afc4-31b5165b7d1e">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329300.169 5730984.255 21.0 329300.169 5730984.255 21.036 329299.756 5730984.519 21.036 329299.756 5730984.519 21.0 329300.169 5730984.255 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_ddd664cc-a2cd-4f34-9876-6c348a5a9a1e">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329300.169 5730984.255 24.232 329300.169 5730984.255 24.592 329299.756 5730984.519 24.584 329299.756 5730984.519 24.232 329300.169 5730984.255 24.232</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_94fb3fbc-ab8a-4253-95b4-3817bac73366">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329300.169 5730984.255 21.036 329300.169 5730984.255 24.232 329299.756 5730984.519 24.232 329299.756 5730984.519 21.036 329300.169 5730984.255 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="GUID_1543405942858_111012018">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>5000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">7.084</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_6"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_2"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_1"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_4"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_0"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_3"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_8"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012018_2_7"/>
                  <gml:surfaceMember xlink:href="#UUID_53ff9e8d-1365-4fa4-842f-25b3ad585ce3"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329309.151 5730993.359 21.017 329309.568 5730994.0 21.017 329310.0 5730994.662 21.037 329310.22 5730995.0 21.04 329310.632 5730995.632 21.04 329310.872 5730996.0 21.039 329311.0 5730996.197 21.036 329311.523 5730997.0 21.015 329312.0 5730997.731 21.017 329312.175 5730998.0 21.024 329312.502 5730998.502 21.025 329312.827 5730999.0 21.032 329313.0 5730999.266 21.033 329313.478 5731000.0 21.04 329313.724 5731000.377 21.07</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329313.724 5731000.377 21.07 329314.0 5731000.197 21.056 329314.119 5731000.119 21.048 329314.303 5731000.0 21.04 329314.725 5730999.725 21.04 329315.0 5730999.545 21.035 329315.33 5730999.33 21.03 329315.837 5730999.0 21.038 329315.936 5730998.936 21.04 329316.0 5730998.894 21.04 329316.541 5730998.541 21.04 329316.556 5730998.532 21.04</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329316.556 5730998.532 21.04 329317.0 5730998.242 21.04 329317.147 5730998.147 21.043 329317.372 5730998.0 21.04 329317.752 5730997.752 21.04 329318.0 5730997.591 21.044 329318.358 5730997.358 21.043 329318.906 5730997.0 21.068 329318.963 5730996.963 21.07 329319.0 5730996.939 21.07 329319.388 5730996.686 21.086</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329314.791 5730989.691 21.098 329314.983 5730989.983 21.1 329314.994 5730990.0 21.1 329315.0 5730990.009 21.1 329315.651 5730991.0 21.067 329316.0 5730991.531 21.065 329316.308 5730992.0 21.064 329316.9 5730992.9 21.07 329316.966 5730993.0 21.07 329317.0 5730993.052 21.069 329317.623 5730994.0 21.041 329318.0 5730994.574 21.047 329318.28 5730995.0 21.063 329318.817 5730995.817 21.068 329318.937 5730996.0 21.069 329319.0 5730996.096 21.07 329319.388 5730996.686 21.086</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329309.151 5730993.359 21.017 329309.277 5730993.277 21.023 329309.704 5730993.0 21.027 329309.883 5730992.883 21.029 329310.0 5730992.807 21.032 329310.489 5730992.489 21.045 329311.0 5730992.157 21.05 329311.095 5730992.095 21.051 329311.241 5730992.0 21.055 329311.701 5730991.701 21.067 329312.0 5730991.506 21.07 329312.307 5730991.307 21.073 329312.778 5730991.0 21.086 329312.913 5730990.913 21.09 329313.0 5730990.856 21.091 329313.519 5730990.519 21.095 329314.0 5730990.205 21.098 329314.125 5730990.125 21.098 329314.316 5730990.0 21.1 329314.73 5730989.73 21.103 329314.791 5730989.691 21.098</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_f2157cb8-693f-4ce1-8735-1b9789c97fee">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_0c09a835-1714-44b9-acb3-d841ff12d5e4">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_1">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_1_0_">
                          <gml:posList srsDimension="3">329309.151 5730993.359 24.658 329313.724 5731000.377 24.658 329313.724 5731000.377 21.0 329309.151 5730993.359 21.0 329309.151 5730993.359 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_52db4694-5569-4ede-b690-cd28db6ffe5b">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_4570166d-cabb-428a-b527-16f48ec2e916">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_2">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_2_0_">
                          <gml:posList srsDimension="3">329313.724 5731000.377 24.658 329316.556 5730998.532 28.084 329316.556 5730998.532 21.0 329313.724 5731000.377 21.0 329313.724 5731000.377 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_492255a3-2dca-42d9-8d34-00c8654ca944">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_e58fd8c3-0f49-43c6-b206-3ff2abc2dfd9">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_3">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_3_0_">
                          <gml:posList srsDimension="3">329316.556 5730998.532 28.084 329319.388 5730996.686 24.658 329319.388 5730996.686 21.0 329316.556 5730998.532 21.0 329316.556 5730998.532 28.084</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_900b80cb-c7b4-42ce-9abb-469653f5f9cd">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_11f1d589-9bf9-495e-8ee7-516cdc073f68">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_4">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_4_0_">
                          <gml:posList srsDimension="3">329319.388 5730996.686 24.658 329314.791 5730989.691 24.658 329314.791 5730989.691 21.0 329319.388 5730996.686 21.0 329319.388 5730996.686 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_08b288f0-0491-4575-b3cc-eb7655ad0f12">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_333b91db-7d89-4083-a70f-5e529cb2640f">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_6">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_6_0_">
                          <gml:posList srsDimension="3">329309.704 5730988.061 28.084 329316.556 5730998.532 28.084 329313.724 5731000.377 24.658 329309.151 5730993.359 24.658 329309.704 5730988.061 28.084</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_092e8295-1dde-48db-be7e-c8ba3ae7ebc4">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_ac01c892-048e-4dde-a16e-5e8d8ce4d667">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_7">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_7_0_">
                          <gml:posList srsDimension="3">329309.704 5730988.061 28.084 329309.151 5730993.359 24.658 329314.791 5730989.691 24.658 329309.704 5730988.061 28.084</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_d40c55f0-b65e-4cef-b1ad-11d1289204a4">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_0b0db581-190b-4927-8c6e-0e7dabe2d29f">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_8">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_8_0_">
                          <gml:posList srsDimension="3">329314.791 5730989.691 24.658 329319.388 5730996.686 24.658 329316.556 5730998.532 28.084 329309.704 5730988.061 28.084 329314.791 5730989.691 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_d8d01089-ab70-482b-a1fe-7f1e045b6519">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_efe40cc4-bfe5-4531-8a0d-752ed5978257">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012018_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012018_2_0_0_">
                          <gml:posList srsDimension="3">329309.151 5730993.359 21.0 329313.724 5731000.377 21.0 329316.556 5730998.532 21.0 329319.388 5730996.686 21.0 329314.791 5730989.691 21.0 329309.151 5730993.359 21.0</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_53ff9e8d-1365-4fa4-842f-25b3ad585ce3">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329314.791 5730989.691 24.658 329309.151 5730993.359 24.658 329309.151 5730993.359 21.0 329314.791 5730989.691 21.0 329314.791 5730989.691 24.658</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="GUID_Vyol45Zm22BarmXF">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>1000</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">3.196</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012014_2_3"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012014_2_0"/>
                  <gml:surfaceMember xlink:href="#UUID_072221db-fa88-4115-a8c3-f5a20aaf9e18"/>
                  <gml:surfaceMember xlink:href="#UUID_a8a4ebc4-6500-49be-907c-04df9b06bc52"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012014_2_5"/>
                  <gml:surfaceMember xlink:href="#UUID_75dcac42-af23-420b-889f-5f0985189418"/>
                  <gml:surfaceMember xlink:href="#UUID_3332306f-425e-4bec-9636-224299a46b6d"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.261 5730983.774 21.043 329299.411 5730984.0 21.046 329299.756 5730984.519 21.053</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.756 5730984.519 21.053 329300.0 5730984.363 21.047 329300.169 5730984.255 21.043</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.67 5730983.503 21.038 329299.999 5730983.999 21.04 329300.0 5730984.0 21.04 329300.169 5730984.255 21.043</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329299.261 5730983.774 21.043 329299.57 5730983.57 21.036 329299.67 5730983.503 21.038</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_9a9936c2-97ff-4e91-9afd-29282d972a96">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_653b52f3-141d-4aa2-bad6-7a43f9c964d2">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012014_2_3">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012014_2_3_0_">
                          <gml:posList srsDimension="3">329300.169 5730984.255 24.232 329299.67 5730983.503 24.232 329299.67 5730983.503 21.036 329300.169 5730984.255 21.036 329300.169 5730984.255 24.232</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_cdd5d373-45cd-4cb8-9ea6-d592990d6d83">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_c3630ae3-82d2-4e9a-af28-c317e923efbb">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012014_2_5">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012014_2_5_0_">
                          <gml:posList srsDimension="3">329299.67 5730983.503 24.232 329300.169 5730984.255 24.232 329299.756 5730984.519 24.232 329299.261 5730983.774 24.232 329299.67 5730983.503 24.232</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_233015fe-3dd6-46d3-ac63-c0d9abef06d6">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_27fd9930-e49e-4de6-9fbf-8130f6e8dc1f">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012014_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012014_2_0_0_">
                          <gml:posList srsDimension="3">329299.261 5730983.774 21.036 329299.756 5730984.519 21.036 329300.169 5730984.255 21.036 329299.67 5730983.503 21.036 329299.261 5730983.774 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_072221db-fa88-4115-a8c3-f5a20aaf9e18">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.261 5730983.774 21.036 329299.261 5730983.774 24.232 329299.756 5730984.519 24.232 329299.756 5730984.519 21.036 329299.261 5730983.774 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_3332306f-425e-4bec-9636-224299a46b6d">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.756 5730984.519 21.036 329299.756 5730984.519 24.232 329300.169 5730984.255 24.232 329300.169 5730984.255 21.036 329299.756 5730984.519 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_04cd2b1f-d02d-4e2e-8589-0b75b11a06ca">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_a8a4ebc4-6500-49be-907c-04df9b06bc52">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.67 5730983.503 24.106 329299.67 5730983.503 24.232 329299.536 5730983.592 24.232 329299.67 5730983.503 24.106</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_75dcac42-af23-420b-889f-5f0985189418">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329299.67 5730983.503 21.036 329299.67 5730983.503 24.106 329299.536 5730983.592 24.232 329299.261 5730983.774 24.232 329299.261 5730983.774 21.036 329299.67 5730983.503 21.036</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
          <bldg:address>
            <core:Address gml:id="UUID_338b3c75-b215-4180-a263-35d68623506b">
              <core:xalAddress>
                <xAL:AddressDetails>
                  <xAL:Country>
                    <xAL:CountryName>Germany</xAL:CountryName>
                    <xAL:Locality Type="Town">
                      <xAL:LocalityName>Wesel</xAL:LocalityName>
                      <xAL:Thoroughfare Type="Street">
                        <xAL:ThoroughfareNumber>19</xAL:ThoroughfareNumber>
                        <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                      </xAL:Thoroughfare>
                    </xAL:Locality>
                  </xAL:Country>
                </xAL:AddressDetails>
              </core:xalAddress>
            </core:Address>
          </bldg:address>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:address>
        <core:Address gml:id="UUID_00491083-81f8-4648-beda-9239851a698e">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>19</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8P">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8P</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:roofType>2100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">5.086</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_6"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012028_2_4"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329167.803 5730489.507 18.308 329167.843 5730489.843 18.317 329167.862 5730490.0 18.318 329167.98 5730490.98 18.328 329167.983 5730491.0 18.329 329168.0 5730491.144 18.33 329168.103 5730492.0 18.335 329168.117 5730492.117 18.336 329168.223 5730493.0 18.357 329168.254 5730493.254 18.363 329168.344 5730494.0 18.374 329168.391 5730494.391 18.383 329168.464 5730495.0 18.399 329168.527 5730495.527 18.406 329168.584 5730496.0 18.413 329168.664 5730496.664 18.423 329168.705 5730497.0 18.434 329168.801 5730497.801 18.46 329168.825 5730498.0 18.467 329168.938 5730498.938 18.506 329168.945 5730499.0 18.511 329169.0 5730499.454 18.524 329169.064 5730499.986 18.541</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329169.064 5730499.986 18.541 329169.866 5730499.866 18.562 329170.0 5730499.846 18.564 329170.736 5730499.736 18.574 329171.0 5730499.697 18.584 329171.606 5730499.606 18.6 329172.0 5730499.547 18.615 329172.476 5730499.476 18.634 329173.0 5730499.398 18.648 329173.346 5730499.346 18.664 329174.0 5730499.248 18.695 329174.216 5730499.216 18.703 329175.0 5730499.099 18.732 329175.086 5730499.086 18.734 329175.661 5730499.0 18.756 329175.956 5730498.956 18.768 329176.0 5730498.949 18.769 329176.826 5730498.826 18.793 329177.0 5730498.8 18.8 329177.053 5730498.792 18.803</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329177.053 5730498.792 18.803 329177.696 5730498.696 18.835 329178.0 5730498.65 18.843 329178.566 5730498.566 18.864 329179.0 5730498.501 18.88 329179.436 5730498.436 18.896 329180.0 5730498.351 18.917 329180.306 5730498.306 18.947 329181.0 5730498.202 18.966 329181.112 5730498.185 18.966</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329179.84 5730487.687 18.756 329179.861 5730487.861 18.781 329179.878 5730488.0 18.788 329179.999 5730488.999 18.75 329179.999 5730489.0 18.75 329180.0 5730489.008 18.75 329180.12 5730490.0 18.762 329180.137 5730490.137 18.767 329180.241 5730491.0 18.818 329180.275 5730491.275 18.82 329180.363 5730492.0 18.852 329180.413 5730492.413 18.866 329180.484 5730493.0 18.886 329180.55 5730493.55 18.899 329180.605 5730494.0 18.886 329180.688 5730494.688 18.894 329180.726 5730495.0 18.895 329180.826 5730495.826 18.905 329180.847 5730496.0 18.908 329180.964 5730496.964 18.919 329180.968 5730497.0 18.919 329181.0 5730497.261 18.928 329181.09 5730498.0 18.953 329181.102 5730498.102 18.959 329181.112 5730498.185 18.966</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329167.803 5730489.507 18.308 329168.0 5730489.477 18.32 329168.415 5730489.415 18.339 329169.0 5730489.326 18.36 329169.283 5730489.283 18.364 329170.0 5730489.175 18.392 329170.152 5730489.152 18.396 329171.0 5730489.024 18.44 329171.021 5730489.021 18.441 329171.156 5730489.0 18.443 329171.889 5730488.889 18.458 329172.0 5730488.872 18.464 329172.758 5730488.758 18.513 329173.0 5730488.721 18.514 329173.626 5730488.626 18.531 329174.0 5730488.57 18.541 329174.495 5730488.495 18.565 329175.0 5730488.419 18.565 329175.364 5730488.364 18.562 329176.0 5730488.268 18.578 329176.232 5730488.232 18.586 329177.0 5730488.116 18.613 329177.101 5730488.101 18.619 329177.77 5730488.0 18.648 329177.97 5730487.97 18.658 329178.0 5730487.965 18.659 329178.838 5730487.838 18.69 329179.0 5730487.814 18.693 329179.707 5730487.707 18.759 329179.84 5730487.687 18.756</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_11d8e4e5-5609-4cf5-a21e-3c728d43111a">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_4a02cabd-0683-4ae1-91ac-aa3ec5f9603e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_1_0_">
                      <gml:posList srsDimension="3">329167.803 5730489.507 20.935 329169.064 5730499.986 20.933 329169.064 5730499.986 18.308 329167.803 5730489.507 18.308 329167.803 5730489.507 20.935</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ea21c98f-7397-4b5f-9f09-220f1ab8a227">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_6405dff2-f907-4f63-9879-bfe4cb752d44">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_2_0_">
                      <gml:posList srsDimension="3">329169.064 5730499.986 20.933 329177.053 5730498.792 22.565 329177.053 5730498.792 18.308 329169.064 5730499.986 18.308 329169.064 5730499.986 20.933</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_0cb2c9b4-4d5e-447e-8a7c-82c323be7d4c">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_04d0da6e-f61f-4ae0-8f10-15b9f6e68f04">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_3_0_">
                      <gml:posList srsDimension="3">329177.053 5730498.792 22.565 329181.112 5730498.185 23.394 329181.112 5730498.185 18.308 329177.053 5730498.792 18.308 329177.053 5730498.792 22.565</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_dd32a7e1-8153-4df7-ba05-e6f822a4a542">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_af6dadb1-6a64-466a-b009-d1585fd50e81">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_4_0_">
                      <gml:posList srsDimension="3">329181.112 5730498.185 23.394 329179.84 5730487.687 23.394 329179.84 5730487.687 18.308 329181.112 5730498.185 18.308 329181.112 5730498.185 23.394</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_1be4d954-e2bb-4653-8d64-b6ff0bcd7ff6">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_deddfab0-0d6a-4e84-aba5-a582a572bd77">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_5_0_">
                      <gml:posList srsDimension="3">329179.84 5730487.687 23.394 329167.803 5730489.507 20.935 329167.803 5730489.507 18.308 329179.84 5730487.687 18.308 329179.84 5730487.687 23.394</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_cacd9917-5218-4d3b-8218-12178284e693">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_7ed069e3-4600-42b9-984b-ddd01ee99c7e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_6_0_">
                      <gml:posList srsDimension="3">329179.84 5730487.687 23.394 329181.112 5730498.185 23.394 329177.053 5730498.792 22.565 329169.064 5730499.986 20.933 329167.803 5730489.507 20.935 329179.84 5730487.687 23.394</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_24aa6988-8fac-4362-9e78-1fb01baa5004">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_9ce6ab78-7017-449a-b355-075ccfa36c43">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012028_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012028_2_0_0_">
                      <gml:posList srsDimension="3">329167.803 5730489.507 18.308 329169.064 5730499.986 18.308 329177.053 5730498.792 18.308 329181.112 5730498.185 18.308 329179.84 5730487.687 18.308 329167.803 5730489.507 18.308</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_0c625992-d0d0-4b98-b5e1-3cca0da78097">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8V">
      <gml:name>Straitmannskath</gml:name>
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8V</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_1210</bldg:function>
      <bldg:roofType>3300</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">8.736</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_13"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_6"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_11"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_12"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_8"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_10"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_9"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_14"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_7"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012024_2_5"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329197.296 5730490.045 19.073 329197.335 5730490.335 19.073 329197.425 5730491.0 19.08 329197.491 5730491.491 19.08 329197.56 5730492.0 19.076 329197.648 5730492.648 19.07 329197.673 5730492.832 19.07</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329197.673 5730492.832 19.07 329197.695 5730493.0 19.07 329197.804 5730493.804 19.07 329197.83 5730494.0 19.07 329197.96 5730494.96 19.07 329197.966 5730495.0 19.07 329198.0 5730495.255 19.07 329198.068 5730495.758 19.07</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329198.068 5730495.758 19.07 329198.1 5730496.0 19.07 329198.116 5730496.116 19.07 329198.234 5730497.0 19.07 329198.27 5730497.27 19.07 329198.351 5730497.882 19.075</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329198.351 5730497.882 19.075 329198.367 5730498.0 19.076 329198.424 5730498.424 19.084 329198.5 5730499.0 19.09 329198.577 5730499.577 19.09 329198.634 5730500.0 19.09 329198.72 5730500.646 19.096</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329198.72 5730500.646 19.096 329199.0 5730500.608 19.096 329199.534 5730500.534 19.101 329200.0 5730500.47 19.099 329200.413 5730500.413 19.094 329201.0 5730500.333 19.093 329201.293 5730500.293 19.09 329202.0 5730500.195 19.074 329202.172 5730500.172 19.07 329203.0 5730500.058 19.07 329203.051 5730500.051 19.071 329203.422 5730500.0 19.066 329203.93 5730499.93 19.061 329204.0 5730499.921 19.061 329204.809 5730499.809 19.07 329205.0 5730499.783 19.07 329205.689 5730499.689 19.07 329206.0 5730499.646 19.066 329206.568 5730499.568 19.06 329207.0 5730499.508 19.055 329207.447 5730499.447 19.046 329208.0 5730499.371 19.046 329208.326 5730499.326 19.047 329209.0 5730499.234 19.032 329209.205 5730499.205 19.034 329210.0 5730499.096 19.032 329210.085 5730499.085 19.033 329210.7 5730499.0 19.016 329210.933 5730498.968 19.012</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329210.554 5730496.172 19.026 329210.614 5730496.614 19.03 329210.666 5730497.0 19.03 329210.771 5730497.771 19.022 329210.802 5730498.0 19.024 329210.928 5730498.928 19.012 329210.933 5730498.968 19.012</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329210.437 5730495.306 19.016 329210.458 5730495.458 19.02 329210.531 5730496.0 19.025 329210.554 5730496.172 19.026</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329209.872 5730491.13 18.87 329209.988 5730491.988 18.9 329209.989 5730492.0 18.9 329210.0 5730492.078 18.902 329210.125 5730493.0 18.928 329210.144 5730493.144 18.931 329210.26 5730494.0 18.992 329210.301 5730494.301 19.004 329210.396 5730495.0 19.008 329210.437 5730495.306 19.016</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329209.495 5730488.348 18.808 329209.518 5730488.518 18.811 329209.583 5730489.0 18.83 329209.675 5730489.675 18.837 329209.719 5730490.0 18.843 329209.831 5730490.831 18.858 329209.854 5730491.0 18.866 329209.872 5730491.13 18.87</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329197.296 5730490.045 19.073 329197.619 5730490.0 19.076 329197.954 5730489.954 19.079 329198.0 5730489.947 19.078 329198.831 5730489.831 19.073 329199.0 5730489.808 19.07 329199.709 5730489.709 19.058 329200.0 5730489.669 19.06 329200.587 5730489.587 19.063 329201.0 5730489.53 19.066 329201.465 5730489.465 19.064 329202.0 5730489.391 19.062 329202.343 5730489.343 19.06 329203.0 5730489.252 19.065 329203.221 5730489.221 19.064 329204.0 5730489.112 19.071 329204.099 5730489.099 19.069 329204.808 5730489.0 19.038 329204.977 5730488.977 19.029 329205.0 5730488.973 19.027 329205.854 5730488.854 18.973 329206.0 5730488.834 18.973 329206.732 5730488.732 18.918 329207.0 5730488.695 18.886 329207.61 5730488.61 18.83 329208.0 5730488.556 18.826 329208.488 5730488.488 18.825 329209.0 5730488.417 18.807 329209.366 5730488.366 18.805 329209.495 5730488.348 18.808</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_2c1fb22a-80ca-487e-b7cf-f1d6b4b548e4">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_e1a6f53b-135a-4524-880d-dc7a139f641e">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_1_0_">
                      <gml:posList srsDimension="3">329197.296 5730490.045 22.225 329197.673 5730492.832 25.021 329197.673 5730492.832 18.805 329197.296 5730490.045 18.805 329197.296 5730490.045 22.225</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_5594df59-d1b8-4f0d-a7b1-a482975a5292">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_7e0a3516-8524-42bd-a6d9-628348cd8372">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_2_0_">
                      <gml:posList srsDimension="3">329197.673 5730492.832 25.021 329198.068 5730495.758 25.009 329198.068 5730495.758 18.805 329197.673 5730492.832 18.805 329197.673 5730492.832 25.021</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_92f6b0e1-11cd-4533-9055-5777d7c67421">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_6343f4ef-e38f-43c6-8a09-3f41e9defe34">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_3_0_">
                      <gml:posList srsDimension="3">329198.068 5730495.758 25.009 329198.351 5730497.882 24.997 329198.351 5730497.882 18.805 329198.068 5730495.758 18.805 329198.068 5730495.758 25.009</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_e98161c1-20b0-4f99-8c0e-17fe0693edd3">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_bad4488d-29d1-4b89-b36d-d06d3e700531">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_4_0_">
                      <gml:posList srsDimension="3">329198.351 5730497.882 24.997 329198.72 5730500.646 22.225 329198.72 5730500.646 18.805 329198.351 5730497.882 18.805 329198.351 5730497.882 24.997</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_aa808747-5eac-40df-a865-69ced877036f">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_974835dc-3b10-4f51-a74a-c13d5120bd78">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_5_0_">
                      <gml:posList srsDimension="3">329198.72 5730500.646 22.225 329210.933 5730498.968 22.225 329210.933 5730498.968 18.805 329198.72 5730500.646 18.805 329198.72 5730500.646 22.225</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_effe5f6c-eeeb-4d52-8570-1bf32f39cc33">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_b0196120-5f5c-4c8e-8b2b-1de25e3829a1">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_6_0_">
                      <gml:posList srsDimension="3">329210.933 5730498.968 22.225 329210.554 5730496.172 25.024 329210.554 5730496.172 18.805 329210.933 5730498.968 18.805 329210.933 5730498.968 22.225</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_84eb8475-0a3c-4b5f-9378-489f27ab015e">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_277dbb36-2c73-47a4-a251-03871a92f47c">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_7">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_7_0_">
                      <gml:posList srsDimension="3">329210.554 5730496.172 25.024 329210.437 5730495.306 25.022 329210.437 5730495.306 18.805 329210.554 5730496.172 18.805 329210.554 5730496.172 25.024</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_653923b4-6cf1-41ed-a705-a552d7812bfa">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_0cd53e82-7902-479f-8f70-f6bf65cd9db1">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_8">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_8_0_">
                      <gml:posList srsDimension="3">329210.437 5730495.306 25.022 329209.872 5730491.13 25.01 329209.872 5730491.13 18.805 329210.437 5730495.306 18.805 329210.437 5730495.306 25.022</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_58098b98-5af0-4b07-940e-b7eee40a3005">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_1ce9c615-8902-4327-a50b-15e2685204f2">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_9">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_9_0_">
                      <gml:posList srsDimension="3">329209.872 5730491.13 25.01 329209.495 5730488.348 22.225 329209.495 5730488.348 18.805 329209.872 5730491.13 18.805 329209.872 5730491.13 25.01</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_3d59759b-9588-4795-ba81-b11b292d1eea">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_39597289-4cca-4699-a199-fdf329ac55f1">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_10">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_10_0_">
                      <gml:posList srsDimension="3">329209.495 5730488.348 22.225 329197.296 5730490.045 22.225 329197.296 5730490.045 18.805 329209.495 5730488.348 18.805 329209.495 5730488.348 22.225</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_63f6faaf-e0ee-433e-8005-a191a03b1d31">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_8954bb36-73f0-4f68-98b0-3cb40047e37b">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_11">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_11_0_">
                      <gml:posList srsDimension="3">329207.727 5730494.002 27.541 329200.02 5730495.067 27.541 329197.673 5730492.832 25.021 329197.296 5730490.045 22.225 329209.495 5730488.348 22.225 329209.872 5730491.13 25.01 329207.727 5730494.002 27.541</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_ad33923a-627e-410b-a5d2-3cad94439c79">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_54217746-7e73-4ad6-ad90-b22ccb45cf31">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_12">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_12_0_">
                      <gml:posList srsDimension="3">329207.727 5730494.002 27.541 329209.872 5730491.13 25.01 329210.437 5730495.306 25.022 329210.554 5730496.172 25.024 329207.727 5730494.002 27.541</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_a8e3d39a-902e-47de-b19c-94e9f908d4d0">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_e06b4e66-2338-4972-b07e-cf0cc17d4493">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_13">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_13_0_">
                      <gml:posList srsDimension="3">329200.02 5730495.067 27.541 329207.727 5730494.002 27.541 329210.554 5730496.172 25.024 329210.933 5730498.968 22.225 329198.72 5730500.646 22.225 329198.351 5730497.882 24.997 329200.02 5730495.067 27.541</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_f0e6269e-77e8-42c1-9df0-ae02112582ce">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_04258360-9101-46cf-b9c1-a39f4a705531">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_14">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_14_0_">
                      <gml:posList srsDimension="3">329200.02 5730495.067 27.541 329198.351 5730497.882 24.997 329198.068 5730495.758 25.009 329197.673 5730492.832 25.021 329200.02 5730495.067 27.541</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_c23d013a-79ac-44d5-b23b-3c5d931585d9">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_1f82f23f-1150-4fbb-8c97-45ff40985e0c">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012024_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012024_2_0_0_">
                      <gml:posList srsDimension="3">329197.296 5730490.045 18.805 329197.673 5730492.832 18.805 329198.068 5730495.758 18.805 329198.351 5730497.882 18.805 329198.72 5730500.646 18.805 329210.933 5730498.968 18.805 329210.554 5730496.172 18.805 329210.437 5730495.306 18.805 329209.872 5730491.13 18.805 329209.495 5730488.348 18.805 329197.296 5730490.045 18.805</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_66ccb68d-e3f6-4905-9906-71a6f0b6675d">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000Gb8S">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000Gb8S</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_2720</bldg:function>
      <bldg:roofType>1000</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">2.557</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_5"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_6"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012027_2_4"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329183.926 5730510.858 18.892 329184.0 5730510.838 18.895 329184.664 5730510.664 18.933 329185.0 5730510.575 18.949 329185.455 5730510.455 18.974 329186.0 5730510.311 18.997 329186.246 5730510.246 19.007 329187.0 5730510.048 19.03 329187.038 5730510.038 19.032 329187.181 5730510.0 19.037 329187.829 5730509.829 19.065 329188.0 5730509.784 19.072 329188.149 5730509.745 19.079</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329188.149 5730509.745 19.079 329188.621 5730509.621 19.099 329189.0 5730509.521 19.115 329189.412 5730509.412 19.149 329190.0 5730509.257 19.197 329190.203 5730509.203 19.208 329190.224 5730509.198 19.211</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329187.8 5730500.159 19.149 329188.0 5730500.905 19.167 329188.026 5730501.0 19.17 329188.035 5730501.035 19.17 329188.294 5730502.0 19.18 329188.401 5730502.401 19.176 329188.562 5730503.0 19.174 329188.768 5730503.768 19.157 329188.83 5730504.0 19.15 329189.0 5730504.634 19.156 329189.098 5730505.0 19.161 329189.134 5730505.134 19.163 329189.366 5730506.0 19.155 329189.501 5730506.501 19.15 329189.635 5730507.0 19.153 329189.867 5730507.867 19.175 329189.903 5730508.0 19.175 329190.0 5730508.363 19.187 329190.171 5730509.0 19.217 329190.224 5730509.198 19.211</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329181.521 5730501.801 19.071 329181.743 5730501.743 19.097 329182.0 5730501.676 19.117 329182.536 5730501.536 19.126 329183.0 5730501.414 19.134 329183.328 5730501.328 19.14 329184.0 5730501.153 19.135 329184.121 5730501.121 19.135 329184.584 5730501.0 19.177 329184.914 5730500.914 19.199 329185.0 5730500.891 19.198 329185.706 5730500.706 19.164 329186.0 5730500.63 19.171 329186.499 5730500.499 19.165 329187.0 5730500.368 19.171 329187.292 5730500.292 19.163 329187.8 5730500.159 19.149</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329181.521 5730501.801 19.071 329181.574 5730502.0 19.073 329181.781 5730502.781 19.033 329181.839 5730503.0 19.034 329182.0 5730503.605 19.022 329182.105 5730504.0 19.011 329182.143 5730504.143 19.009 329182.37 5730505.0 18.987 329182.504 5730505.504 18.985 329182.636 5730506.0 18.979 329182.866 5730506.866 18.96 329182.902 5730507.0 18.958 329183.0 5730507.371 18.949 329183.167 5730508.0 18.933 329183.227 5730508.227 18.932 329183.433 5730509.0 18.923 329183.589 5730509.589 18.916 329183.698 5730510.0 18.911 329183.926 5730510.858 18.892</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_14d85ace-6a92-4f58-8ef9-5263c9bb408e">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_536eff5b-2003-4ba9-867f-a9752e29a378">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_1_0_">
                      <gml:posList srsDimension="3">329183.926 5730510.858 21.449 329188.149 5730509.745 21.449 329188.149 5730509.745 18.892 329183.926 5730510.858 18.892 329183.926 5730510.858 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_84ccb941-2040-4804-8c1c-843d1a99bb6a">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_29b8d2d2-5076-499f-a984-5c348da74c4d">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_2_0_">
                      <gml:posList srsDimension="3">329188.149 5730509.745 21.449 329190.224 5730509.198 21.449 329190.224 5730509.198 18.892 329188.149 5730509.745 18.892 329188.149 5730509.745 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ad83c757-8a08-4109-b77f-85cfce9382ef">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_ca8c7aca-58e9-4a52-ac08-0dcbd71facc6">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_3_0_">
                      <gml:posList srsDimension="3">329190.224 5730509.198 21.449 329187.8 5730500.159 21.449 329187.8 5730500.159 18.892 329190.224 5730509.198 18.892 329190.224 5730509.198 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_6b745257-905b-4dc9-8f1a-b3939c3b9ccf">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_40bd5d76-603c-4c72-a7fa-9c0a234ef633">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_4_0_">
                      <gml:posList srsDimension="3">329187.8 5730500.159 21.449 329181.521 5730501.801 21.449 329181.521 5730501.801 18.892 329187.8 5730500.159 18.892 329187.8 5730500.159 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_beadb3fd-20f0-4cb1-ba1d-0c3ec2536866">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_319301a4-b90a-48c8-8e9b-b69f8d935db2">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_5_0_">
                      <gml:posList srsDimension="3">329181.521 5730501.801 21.449 329183.926 5730510.858 21.449 329183.926 5730510.858 18.892 329181.521 5730501.801 18.892 329181.521 5730501.801 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_80a851c8-a784-4269-8258-0c0c3012a407">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_a96241c9-bf77-4745-b989-86715e84cb91">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_6_0_">
                      <gml:posList srsDimension="3">329181.521 5730501.801 21.449 329187.8 5730500.159 21.449 329190.224 5730509.198 21.449 329188.149 5730509.745 21.449 329183.926 5730510.858 21.449 329181.521 5730501.801 21.449</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_a4fdd67e-3f78-4794-ba81-d184fb415eae">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_807e896f-492c-4379-8f5b-10a075ce64dd">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012027_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012027_2_0_0_">
                      <gml:posList srsDimension="3">329183.926 5730510.858 18.892 329188.149 5730509.745 18.892 329190.224 5730509.198 18.892 329187.8 5730500.159 18.892 329181.521 5730501.801 18.892 329183.926 5730510.858 18.892</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_ed593c3d-76a3-4bae-9fb8-00534fc65790">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>20</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000rD7P">
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000rD7P</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_1010</bldg:function>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="UUID_13d12d1a-7529-4475-8145-c5135f1ba1eb">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>3200</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">6.861</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_2"/>
                  <gml:surfaceMember xlink:href="#UUID_548efd3c-7642-43e8-81db-0b0c40408040"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_6"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_9"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_7"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_8"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_1"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_4"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_10"/>
                  <gml:surfaceMember xlink:href="#UUID_b803eeea-03e1-4e46-a63f-4ca3094c1f1e"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_0"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012025_2_3"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329272.201 5730953.243 22.021 329272.707 5730954.0 21.988 329273.0 5730954.438 21.996 329273.376 5730955.0 21.982 329274.0 5730955.933 21.961 329274.045 5730956.0 21.958 329274.135 5730956.135 21.952 329274.714 5730957.0 21.914 329275.0 5730957.428 21.9 329275.382 5730958.0 21.9 329276.0 5730958.924 21.909 329276.051 5730959.0 21.909 329276.154 5730959.154 21.908 329276.578 5730959.788 21.902</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329276.578 5730959.788 21.902 329276.704 5730959.704 21.903 329277.0 5730959.509 21.9 329277.307 5730959.307 21.903 329277.77 5730959.0 21.9 329277.909 5730958.909 21.899 329278.0 5730958.848 21.898 329278.511 5730958.511 21.89 329279.0 5730958.187 21.898 329279.113 5730958.113 21.899 329279.284 5730958.0 21.897 329279.715 5730957.715 21.896 329280.0 5730957.526 21.899 329280.317 5730957.317 21.907 329280.797 5730957.0 21.91 329280.919 5730956.919 21.912 329281.0 5730956.866 21.913 329281.521 5730956.521 21.925 329282.0 5730956.205 21.944 329282.123 5730956.123 21.948 329282.31 5730956.0 21.959 329282.725 5730955.725 21.977 329283.0 5730955.544 21.994 329283.327 5730955.327 22.01 329283.823 5730955.0 22.043 329283.93 5730954.93 22.05 329284.0 5730954.883 22.052 329284.532 5730954.532 22.075 329285.0 5730954.222 22.072 329285.134 5730954.134 22.077 329285.336 5730954.0 22.063 329285.736 5730953.736 22.016 329286.0 5730953.561 21.927 329286.338 5730953.338 21.871 329286.849 5730953.0 21.753 329286.94 5730952.94 21.738 329287.0 5730952.9 21.716 329287.542 5730952.542 21.605 329288.0 5730952.239 21.39 329288.144 5730952.144 21.313 329288.362 5730952.0 21.19 329288.746 5730951.746 21.002 329289.0 5730951.579 20.881 329289.348 5730951.348 20.807 329289.47 5730951.268 20.785</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329288.972 5730950.526 20.496 329289.0 5730950.568 20.503 329289.29 5730951.0 20.67 329289.47 5730951.268 20.785</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329285.058 5730944.69 20.364 329285.266 5730945.0 20.371 329285.807 5730945.807 20.334 329285.936 5730946.0 20.331 329286.0 5730946.095 20.327 329286.607 5730947.0 20.299 329287.0 5730947.586 20.275 329287.278 5730948.0 20.286 329287.844 5730948.844 20.308 329287.948 5730949.0 20.323 329288.0 5730949.077 20.328 329288.619 5730950.0 20.401 329288.972 5730950.526 20.496</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329279.516 5730948.377 21.607 329280.0 5730948.055 21.451 329280.033 5730948.033 21.44 329280.083 5730948.0 21.426 329280.634 5730947.634 21.31 329281.0 5730947.39 21.239 329281.234 5730947.234 21.204 329281.586 5730947.0 21.12 329281.835 5730946.835 21.063 329282.0 5730946.725 21.02 329282.435 5730946.435 20.905 329283.0 5730946.059 20.775 329283.036 5730946.036 20.768 329283.089 5730946.0 20.757 329283.636 5730945.636 20.674 329284.0 5730945.394 20.569 329284.237 5730945.237 20.521 329284.593 5730945.0 20.447 329284.837 5730944.837 20.401 329285.0 5730944.729 20.371 329285.058 5730944.69 20.364</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329272.201 5730953.243 22.021 329272.226 5730953.226 22.023 329272.566 5730953.0 22.013 329272.827 5730952.827 22.0 329273.0 5730952.711 22.006 329273.427 5730952.427 22.007 329274.0 5730952.046 21.99 329274.028 5730952.028 21.99 329274.07 5730952.0 21.99 329274.628 5730951.628 21.99 329275.0 5730951.381 21.996 329275.229 5730951.229 22.0 329275.573 5730951.0 22.0 329275.829 5730950.829 21.997 329276.0 5730950.716 21.997 329276.43 5730950.43 21.994 329277.0 5730950.051 22.0 329277.03 5730950.03 22.0 329277.076 5730950.0 21.995 329277.631 5730949.631 21.958 329278.0 5730949.385 21.903 329278.231 5730949.231 21.878 329278.579 5730949.0 21.776 329278.832 5730948.832 21.718 329279.0 5730948.72 21.68 329279.433 5730948.433 21.634 329279.516 5730948.377 21.607</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_c7fd5260-934d-46e1-9958-58d6af44d3c9">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_f2f6936f-0fac-4644-a481-42359a5c05a5">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_1">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_1_0_">
                          <gml:posList srsDimension="3">329272.201 5730953.243 25.15 329276.578 5730959.788 25.15 329276.578 5730959.788 20.275 329272.201 5730953.243 20.275 329272.201 5730953.243 25.15</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_fc3641b9-6e86-4a06-b674-57debdda0999">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_84b030ed-cbde-4f52-bc8b-34f8cb129852">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_2">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_2_0_">
                          <gml:posList srsDimension="3">329276.578 5730959.788 25.15 329289.47 5730951.268 25.15 329289.47 5730951.268 20.275 329276.578 5730959.788 20.275 329276.578 5730959.788 25.15</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_04ca15f2-e675-47ec-9413-5fba26d76611">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_a2b3e7c5-3418-47de-bc81-a04804d6e37d">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_3">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_3_0_">
                          <gml:posList srsDimension="3">329289.47 5730951.268 25.15 329288.972 5730950.526 25.15 329288.972 5730950.526 20.275 329289.47 5730951.268 20.275 329289.47 5730951.268 25.15</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_e2545d6f-3d9b-449f-babb-78f821d1de2b">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_6f0d5671-2ba5-43fd-a939-9e4b6c06da37">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_4">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_4_0_">
                          <gml:posList srsDimension="3">329288.972 5730950.526 25.15 329285.058 5730944.69 25.15 329285.058 5730944.69 20.275 329288.972 5730950.526 20.275 329288.972 5730950.526 25.15</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_f194dc1d-527f-4fdc-af1c-03dce7b2bddf">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_daf02600-98ce-46df-b032-7539d5c0c7d7">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_6">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_6_0_">
                          <gml:posList srsDimension="3">329279.516 5730948.377 25.15 329272.201 5730953.243 25.15 329272.201 5730953.243 20.275 329279.516 5730948.377 20.275 329279.516 5730948.377 25.15</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_344a503f-4d8d-4c01-a135-6523299e73b8">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_50c4f446-cbf5-498a-bfc7-99b2e7c3835a">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_7">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_7_0_">
                          <gml:posList srsDimension="3">329277.837 5730954.23 27.136 329283.817 5730950.265 27.136 329289.47 5730951.268 25.15 329276.578 5730959.788 25.15 329277.837 5730954.23 27.136</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_26671c88-de07-44e2-89bc-9008aaa8a3dd">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_e47966f8-9272-45ed-a5fd-15aee210bcf5">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_8">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_8_0_">
                          <gml:posList srsDimension="3">329277.837 5730954.23 27.136 329276.578 5730959.788 25.15 329272.201 5730953.243 25.15 329277.837 5730954.23 27.136</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_92d57c3b-0609-4f17-9e63-88f93519a074">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_232c6d47-ef1f-4bbb-87ee-630dfb471486">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_9">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_9_0_">
                          <gml:posList srsDimension="3">329283.817 5730950.265 27.136 329277.837 5730954.23 27.136 329272.201 5730953.243 25.15 329279.516 5730948.377 25.15 329285.058 5730944.69 25.15 329283.817 5730950.265 27.136</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_9c2ac41b-6623-4745-9f6c-afea0f2e8dac">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_ac36649d-5f35-4dbd-8db0-459920411a75">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_10">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_10_0_">
                          <gml:posList srsDimension="3">329283.817 5730950.265 27.136 329285.058 5730944.69 25.15 329288.972 5730950.526 25.15 329289.47 5730951.268 25.15 329283.817 5730950.265 27.136</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_4238e6d4-880f-4296-83c9-4d14d4f73bbc">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_10592a9a-3364-4e05-9cba-f29b30be5a4a">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012025_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012025_2_0_0_">
                          <gml:posList srsDimension="3">329272.201 5730953.243 20.275 329276.578 5730959.788 20.275 329289.47 5730951.268 20.275 329288.972 5730950.526 20.275 329285.058 5730944.69 20.275 329279.516 5730948.377 20.275 329272.201 5730953.243 20.275</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_1477124f-f37b-4157-8ef2-e604cdf93766">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_548efd3c-7642-43e8-81db-0b0c40408040">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329285.058 5730944.69 25.12 329285.058 5730944.69 25.15 329279.516 5730948.377 25.15 329279.516 5730948.377 25.12 329285.058 5730944.69 25.12</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_b803eeea-03e1-4e46-a63f-4ca3094c1f1e">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329279.516 5730948.377 25.12 329279.516 5730948.377 20.275 329285.058 5730944.69 20.275 329285.058 5730944.69 25.12 329279.516 5730948.377 25.12</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:consistsOfBuildingPart>
        <bldg:BuildingPart gml:id="GUID_1543405942858_111012026">
          <core:creationDate>2021-01-23</core:creationDate>
          <gen:stringAttribute name="DatenquelleDachhoehe">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleBodenhoehe">
            <gen:value>1100</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="DatenquelleLage">
            <gen:value>1000</gen:value>
          </gen:stringAttribute>
          <gen:stringAttribute name="Grundrissaktualitaet">
            <gen:value>2020-07-01</gen:value>
          </gen:stringAttribute>
          <bldg:roofType>3200</bldg:roofType>
          <bldg:measuredHeight uom="urn:adv:uom:m">6.416</bldg:measuredHeight>
          <bldg:lod2Solid>
            <gml:Solid>
              <gml:exterior>
                <gml:CompositeSurface>
                  <gml:surfaceMember xlink:href="#UUID_1353c3fb-e146-418f-ba64-4f4f9dc70985"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_6"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_7"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_0"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_8"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_3"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_5"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_1"/>
                  <gml:surfaceMember xlink:href="#GUID_1543405942858_111012026_2_4"/>
                </gml:CompositeSurface>
              </gml:exterior>
            </gml:Solid>
          </bldg:lod2Solid>
          <bldg:lod2TerrainIntersection>
            <gml:MultiCurve>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329276.666 5730944.053 22.004 329277.0 5730944.56 22.026 329277.29 5730945.0 21.998 329277.851 5730945.851 21.919 329277.949 5730946.0 21.906 329278.0 5730946.077 21.898 329278.608 5730947.0 21.694 329279.0 5730947.594 21.61 329279.268 5730948.0 21.579 329279.516 5730948.377 21.607</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329279.516 5730948.377 21.607 329280.0 5730948.055 21.451 329280.033 5730948.033 21.44 329280.083 5730948.0 21.426 329280.634 5730947.634 21.31 329281.0 5730947.39 21.239 329281.234 5730947.234 21.204 329281.586 5730947.0 21.12 329281.835 5730946.835 21.063 329282.0 5730946.725 21.02 329282.435 5730946.435 20.905 329283.0 5730946.059 20.775 329283.036 5730946.036 20.768 329283.089 5730946.0 20.757 329283.636 5730945.636 20.674 329284.0 5730945.394 20.569 329284.237 5730945.237 20.521 329284.593 5730945.0 20.447 329284.837 5730944.837 20.401 329285.0 5730944.729 20.371 329285.058 5730944.69 20.364</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329282.189 5730940.413 21.266 329282.583 5730941.0 20.932 329283.0 5730941.622 20.659 329283.253 5730942.0 20.572 329283.77 5730942.77 20.401 329283.924 5730943.0 20.357 329284.0 5730943.113 20.345 329284.595 5730944.0 20.377 329285.0 5730944.604 20.362 329285.058 5730944.69 20.364</gml:posList>
                </gml:LineString>
              </gml:curveMember>
              <gml:curveMember>
                <gml:LineString>
                  <gml:posList srsDimension="3">329276.666 5730944.053 22.004 329276.746 5730944.0 22.007 329276.899 5730943.899 22.003 329277.0 5730943.833 22.007 329277.502 5730943.502 21.97 329278.0 5730943.174 22.041 329278.105 5730943.105 22.028 329278.264 5730943.0 22.01 329278.708 5730942.708 21.891 329279.0 5730942.515 21.934 329279.31 5730942.31 21.892 329279.781 5730942.0 21.931 329279.913 5730941.913 21.91 329280.0 5730941.856 21.917 329280.516 5730941.516 21.704 329281.0 5730941.197 21.785 329281.119 5730941.119 21.768 329281.298 5730941.0 21.677 329281.721 5730940.721 21.415 329282.0 5730940.538 21.353 329282.189 5730940.413 21.266</gml:posList>
                </gml:LineString>
              </gml:curveMember>
            </gml:MultiCurve>
          </bldg:lod2TerrainIntersection>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_353b6da6-4cc7-4bb2-8ae8-98f05d79fe1d">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_4988d74f-6afc-4efe-b626-afa3e6825c16">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_1">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_1_0_">
                          <gml:posList srsDimension="3">329276.666 5730944.053 25.12 329279.516 5730948.377 25.12 329279.516 5730948.377 20.275 329276.666 5730944.053 20.275 329276.666 5730944.053 25.12</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_c5e824bb-4261-4397-9c2e-0171cf18f125">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_2e568dc6-984b-4244-8694-321308bb18c9">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_3">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_3_0_">
                          <gml:posList srsDimension="3">329285.058 5730944.69 25.12 329282.189 5730940.413 25.12 329282.189 5730940.413 20.275 329285.058 5730944.69 20.275 329285.058 5730944.69 25.12</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:WallSurface gml:id="UUID_d08a13a1-05a2-4d76-b73a-e236c8af232d">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_2a005fd2-713f-4dc9-accf-5bb6e3dcee76">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_4">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_4_0_">
                          <gml:posList srsDimension="3">329282.189 5730940.413 25.12 329276.666 5730944.053 25.12 329276.666 5730944.053 20.275 329282.189 5730940.413 20.275 329282.189 5730940.413 25.12</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:WallSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_6da7f68f-e8af-4ac9-839b-96201a37226a">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_36e7095f-6110-42c6-9a18-62a8b79d25ae">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_5">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_5_0_">
                          <gml:posList srsDimension="3">329281.501 5730943.957 26.691 329280.213 5730944.81 26.691 329276.666 5730944.053 25.12 329282.189 5730940.413 25.12 329281.501 5730943.957 26.691</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_3a975eac-ef20-434d-a3a5-9007c792cfef">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_168fcfd3-1043-4b37-88b4-4d6e1959c2a1">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_6">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_6_0_">
                          <gml:posList srsDimension="3">329281.501 5730943.957 26.691 329282.189 5730940.413 25.12 329285.058 5730944.69 25.12 329281.501 5730943.957 26.691</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_7a2e4bec-1652-4f38-ab03-0b512b3fb7e1">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_c3b30f1b-bc98-4598-a387-3500907d27b7">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_7">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_7_0_">
                          <gml:posList srsDimension="3">329280.213 5730944.81 26.691 329281.501 5730943.957 26.691 329285.058 5730944.69 25.12 329279.516 5730948.377 25.12 329280.213 5730944.81 26.691</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:RoofSurface gml:id="UUID_53fe7149-f403-4927-be4c-eb51a5a88d5a">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_8df62882-1a9c-4568-8810-1762c31cec10">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_8">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_8_0_">
                          <gml:posList srsDimension="3">329280.213 5730944.81 26.691 329279.516 5730948.377 25.12 329276.666 5730944.053 25.12 329280.213 5730944.81 26.691</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:RoofSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:GroundSurface gml:id="UUID_1f379014-ba28-41a8-b114-b061b25269d0">
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface gml:id="UUID_f7affdfb-4749-4716-9d43-105bfef767fa">
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="GUID_1543405942858_111012026_2_0">
                      <gml:exterior>
                        <gml:LinearRing gml:id="GUID_1543405942858_111012026_2_0_0_">
                          <gml:posList srsDimension="3">329276.666 5730944.053 20.275 329279.516 5730948.377 20.275 329285.058 5730944.69 20.275 329282.189 5730940.413 20.275 329276.666 5730944.053 20.275</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:GroundSurface>
          </bldg:boundedBy>
          <bldg:boundedBy>
            <bldg:ClosureSurface>
              <core:creationDate>2021-01-23</core:creationDate>
              <bldg:lod2MultiSurface>
                <gml:MultiSurface>
                  <gml:surfaceMember>
                    <gml:Polygon gml:id="UUID_1353c3fb-e146-418f-ba64-4f4f9dc70985">
                      <gml:exterior>
                        <gml:LinearRing>
                          <gml:posList srsDimension="3">329279.516 5730948.377 20.275 329279.516 5730948.377 25.12 329285.058 5730944.69 25.12 329285.058 5730944.69 20.275 329279.516 5730948.377 20.275</gml:posList>
                        </gml:LinearRing>
                      </gml:exterior>
                    </gml:Polygon>
                  </gml:surfaceMember>
                </gml:MultiSurface>
              </bldg:lod2MultiSurface>
            </bldg:ClosureSurface>
          </bldg:boundedBy>
        </bldg:BuildingPart>
      </bldg:consistsOfBuildingPart>
      <bldg:address>
        <core:Address gml:id="UUID_d7d9110f-0a3c-4b78-868c-d6b9872b281b">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>19a</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
  <core:cityObjectMember>
    <bldg:Building gml:id="DENW34AL0000rD7Q">
      <gml:name>Schoyekampshof</gml:name>
      <core:creationDate>2021-01-23</core:creationDate>
      <core:externalReference>
        <core:informationSystem>http://repository.gdi-de.org/schemas/adv/citygml/fdv/art.htm#_9100</core:informationSystem>
        <core:externalObject>
          <core:name>DENW34AL0000rD7Q</core:name>
        </core:externalObject>
      </core:externalReference>
      <gen:stringAttribute name="DatenquelleDachhoehe">
        <gen:value>6000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Geometrietyp2DReferenz">
        <gen:value>3000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Gemeindeschluessel">
        <gen:value>05170048</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleBodenhoehe">
        <gen:value>1100</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="DatenquelleLage">
        <gen:value>1000</gen:value>
      </gen:stringAttribute>
      <gen:stringAttribute name="Grundrissaktualitaet">
        <gen:value>2020-07-01</gen:value>
      </gen:stringAttribute>
      <bldg:function>31001_1210</bldg:function>
      <bldg:roofType>3100</bldg:roofType>
      <bldg:measuredHeight uom="urn:adv:uom:m">8.913</bldg:measuredHeight>
      <bldg:lod2Solid>
        <gml:Solid>
          <gml:exterior>
            <gml:CompositeSurface>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_0"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_4"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_10"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_15"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_6"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_12"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_8"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_9"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_1"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_11"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_7"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_13"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_14"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_2"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_3"/>
              <gml:surfaceMember xlink:href="#GUID_1543405942858_111012029_2_5"/>
            </gml:CompositeSurface>
          </gml:exterior>
        </gml:Solid>
      </bldg:lod2Solid>
      <bldg:lod2TerrainIntersection>
        <gml:MultiCurve>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329296.88 5730986.581 21.116 329297.0 5730986.762 21.118 329297.157 5730987.0 21.117 329297.465 5730987.465 21.111 329297.819 5730988.0 21.104 329298.0 5730988.273 21.1 329298.481 5730989.0 21.095 329299.0 5730989.784 21.09 329299.143 5730990.0 21.087 329299.423 5730990.423 21.082 329299.805 5730991.0 21.074 329300.0 5730991.295 21.07 329300.295 5730991.74 21.067</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329295.934 5730987.176 21.14 329296.0 5730987.134 21.139 329296.083 5730987.083 21.138 329296.214 5730987.0 21.136 329296.696 5730986.696 21.117 329296.88 5730986.581 21.116</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329295.837 5730987.027 21.143 329295.934 5730987.176 21.14</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329292.3 5730989.355 21.119 329292.333 5730989.333 21.12 329292.839 5730989.0 21.122 329292.936 5730988.936 21.123 329293.0 5730988.894 21.126 329293.539 5730988.539 21.148 329294.0 5730988.236 21.151 329294.142 5730988.142 21.157 329294.359 5730988.0 21.156 329294.745 5730987.745 21.147 329295.0 5730987.578 21.154 329295.349 5730987.349 21.15 329295.837 5730987.027 21.143</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329292.3 5730989.355 21.119 329292.365 5730989.464 21.115</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329287.836 5730992.438 21.132 329288.0 5730992.33 21.13 329288.199 5730992.199 21.132 329288.503 5730992.0 21.125 329288.803 5730991.803 21.11 329289.0 5730991.674 21.103 329289.407 5730991.407 21.09 329290.0 5730991.017 21.089 329290.01 5730991.01 21.09 329290.026 5730991.0 21.089 329290.614 5730990.614 21.089 329291.0 5730990.36 21.064 329291.218 5730990.218 21.06 329291.549 5730990.0 21.076 329291.821 5730989.821 21.092 329292.0 5730989.704 21.102 329292.365 5730989.464 21.115</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329287.518 5730992.643 21.141 329287.594 5730992.594 21.135 329287.836 5730992.438 21.132</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329287.518 5730992.643 21.141 329287.754 5730993.0 21.112 329288.0 5730993.373 21.083 329288.415 5730994.0 21.062 329289.0 5730994.886 21.041 329289.075 5730995.0 21.04 329289.222 5730995.222 21.04 329289.736 5730996.0 21.037 329290.0 5730996.4 21.036 329290.397 5730997.0 21.03 329290.917 5730997.787 21.03</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329290.917 5730997.787 21.03 329291.0 5730997.913 21.03 329291.057 5730998.0 21.03 329291.169 5730998.169 21.032 329291.718 5730999.0 21.04 329292.0 5730999.427 21.04 329292.379 5731000.0 21.036 329293.0 5731000.941 21.039 329293.039 5731001.0 21.04 329293.116 5731001.116 21.042 329293.7 5731002.0 21.06 329294.0 5731002.454 21.074 329294.315 5731002.931 21.085</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329294.315 5731002.931 21.085 329294.687 5731002.687 21.074 329295.0 5731002.482 21.07 329295.291 5731002.291 21.066 329295.735 5731002.0 21.06 329295.895 5731001.895 21.058 329296.0 5731001.827 21.055 329296.499 5731001.499 21.045 329297.0 5731001.171 21.035 329297.103 5731001.103 21.032 329297.261 5731001.0 21.03 329297.707 5731000.707 21.027 329298.0 5731000.516 21.025 329298.312 5731000.312 21.026 329298.787 5731000.0 21.02 329298.916 5730999.916 21.019 329299.0 5730999.86 21.019 329299.118 5730999.783 21.015</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329299.118 5730999.783 21.015 329299.191 5730999.861 21.015</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329299.191 5730999.861 21.015 329299.596 5730999.596 21.004 329300.0 5730999.331 21.0 329300.2 5730999.2 21.002 329300.504 5730999.0 21.0 329300.804 5730998.804 21.006 329301.0 5730998.675 21.006 329301.408 5730998.408 21.016 329302.0 5730998.019 21.03 329302.012 5730998.012 21.03 329302.03 5730998.0 21.03 329302.616 5730997.616 21.03 329303.0 5730997.364 21.03 329303.22 5730997.22 21.028 329303.555 5730997.0 21.03 329303.709 5730996.899 21.031</gml:posList>
            </gml:LineString>
          </gml:curveMember>
          <gml:curveMember>
            <gml:LineString>
              <gml:posList srsDimension="3">329300.295 5730991.74 21.067 329300.467 5730992.0 21.065 329301.0 5730992.806 21.06 329301.128 5730993.0 21.059 329301.38 5730993.38 21.056 329301.79 5730994.0 21.052 329302.0 5730994.317 21.047 329302.452 5730995.0 21.04 329303.0 5730995.828 21.04 329303.114 5730996.0 21.04 329303.337 5730996.337 21.037 329303.709 5730996.899 21.031</gml:posList>
            </gml:LineString>
          </gml:curveMember>
        </gml:MultiCurve>
      </bldg:lod2TerrainIntersection>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_a6aa5c39-b27e-4272-89dc-e81503f2bd31">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_871761c5-350f-47cc-b3ec-aa3396bd6577">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_1">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_1_0_">
                      <gml:posList srsDimension="3">329300.295 5730991.74 29.913 329296.88 5730986.581 24.793 329296.88 5730986.581 21.0 329300.295 5730991.74 21.0 329300.295 5730991.74 29.913</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_e4886c9c-abe8-42a5-a905-ac145eadf1d5">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_eadc080f-e787-4322-8798-ad9869d5265b">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_2">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_2_0_">
                      <gml:posList srsDimension="3">329296.88 5730986.581 24.793 329295.934 5730987.176 24.781 329295.934 5730987.176 21.0 329296.88 5730986.581 21.0 329296.88 5730986.581 24.793</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_b7caaf0f-e403-4d75-bd91-898106c25192">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_822ce242-35be-4807-aada-02e0d0787332">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_3">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_3_0_">
                      <gml:posList srsDimension="3">329295.934 5730987.176 24.781 329295.837 5730987.027 24.633 329295.837 5730987.027 21.0 329295.934 5730987.176 21.0 329295.934 5730987.176 24.781</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_65290faa-ad1c-4557-aaf5-3b88a808afe5">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_5cca7c7c-3561-4fa5-a7a7-0869997740d1">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_4">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_4_0_">
                      <gml:posList srsDimension="3">329295.837 5730987.027 24.633 329292.3 5730989.355 24.659 329292.3 5730989.355 21.0 329295.837 5730987.027 21.0 329295.837 5730987.027 24.633</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_3f23ae48-6f67-4e29-8bcc-741a4e2b8a8b">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_ba4b2c1f-0e23-4102-9088-95357534a252">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_5">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_5_0_">
                      <gml:posList srsDimension="3">329292.3 5730989.355 24.659 329292.365 5730989.464 24.765 329292.365 5730989.464 21.0 329292.3 5730989.355 21.0 329292.3 5730989.355 24.659</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ba82e2d9-c3aa-4f3a-b134-2d9be9ce964e">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_ee6e4d49-48ee-445e-aff5-5e1b4eb99773">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_6">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_6_0_">
                      <gml:posList srsDimension="3">329292.365 5730989.464 24.765 329287.836 5730992.438 24.794 329287.836 5730992.438 21.0 329292.365 5730989.464 21.0 329292.365 5730989.464 24.765</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_8902eaa4-ba0b-420d-8589-4da1be1a93e6">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_d1ffafd7-471e-4ae2-854b-e30e44014e08">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_7">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_7_0_">
                      <gml:posList srsDimension="3">329287.836 5730992.438 24.794 329287.518 5730992.643 24.793 329287.518 5730992.643 21.0 329287.836 5730992.438 21.0 329287.836 5730992.438 24.794</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_c1f4782e-68c7-441e-9647-e8873f024ca7">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_3b219287-a802-4c61-9caf-e0cfe0170eae">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_8">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_8_0_">
                      <gml:posList srsDimension="3">329287.518 5730992.643 24.793 329290.917 5730997.787 29.913 329290.917 5730997.787 21.0 329287.518 5730992.643 21.0 329287.518 5730992.643 24.793</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ad66baf6-e8c7-44e9-b6f3-fd2d51b8b933">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c28c1e46-fded-44c9-aeb8-2b57ce9ad665">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_9">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_9_0_">
                      <gml:posList srsDimension="3">329290.917 5730997.787 29.913 329294.315 5731002.931 24.793 329294.315 5731002.931 21.0 329290.917 5730997.787 21.0 329290.917 5730997.787 29.913</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_ebc3568f-6310-4d4f-a796-fac8fa863248">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_7ffbbc3c-9f9a-4f3a-b383-089a46908e0f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_10">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_10_0_">
                      <gml:posList srsDimension="3">329294.315 5731002.931 24.793 329299.118 5730999.783 24.837 329299.118 5730999.783 21.0 329294.315 5731002.931 21.0 329294.315 5731002.931 24.793</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_d5237bd8-4647-4a39-8390-7afaaab23ba5">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_d116aba9-2850-4482-82ef-3f5d4211c829">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_11">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_11_0_">
                      <gml:posList srsDimension="3">329299.118 5730999.783 24.837 329299.191 5730999.861 24.75 329299.191 5730999.861 21.0 329299.118 5730999.783 21.0 329299.118 5730999.783 24.837</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_f47c66ac-502f-42fe-91bc-bbdc23e65b51">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_a2ef5a23-4de3-4180-9f79-f63d76fae9af">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_12">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_12_0_">
                      <gml:posList srsDimension="3">329299.191 5730999.861 24.75 329303.709 5730996.899 24.793 329303.709 5730996.899 21.0 329299.191 5730999.861 21.0 329299.191 5730999.861 24.75</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:WallSurface gml:id="UUID_1a646a46-a6cb-4b73-b675-ff86405ce846">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_41e863d8-7e69-46a2-b1e1-41ab10b1a909">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_13">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_13_0_">
                      <gml:posList srsDimension="3">329303.709 5730996.899 24.793 329300.295 5730991.74 29.913 329300.295 5730991.74 21.0 329303.709 5730996.899 21.0 329303.709 5730996.899 24.793</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:WallSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_8a07a223-ecb9-4377-b9a6-2686c6728eb9">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_081d4a4d-377b-4d7a-b17f-a13d940295e2">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_14">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_14_0_">
                      <gml:posList srsDimension="3">329290.917 5730997.787 29.913 329287.518 5730992.643 24.793 329287.836 5730992.438 24.794 329292.365 5730989.464 24.765 329292.3 5730989.355 24.659 329295.837 5730987.027 24.633 329295.934 5730987.176 24.781 329296.88 5730986.581 24.793 329300.295 5730991.74 29.913 329290.917 5730997.787 29.913</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:RoofSurface gml:id="UUID_eac2f2d6-4ce4-44b9-81e2-cfd69cc23698">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_c64283b3-68d0-4902-b321-5a53d5423bd2">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_15">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_15_0_">
                      <gml:posList srsDimension="3">329300.295 5730991.74 29.913 329303.709 5730996.899 24.793 329299.191 5730999.861 24.75 329299.118 5730999.783 24.837 329294.315 5731002.931 24.793 329290.917 5730997.787 29.913 329300.295 5730991.74 29.913</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:RoofSurface>
      </bldg:boundedBy>
      <bldg:boundedBy>
        <bldg:GroundSurface gml:id="UUID_33c2e4e0-0821-4511-acdb-d7fbc7d80b1a">
          <core:creationDate>2021-01-23</core:creationDate>
          <bldg:lod2MultiSurface>
            <gml:MultiSurface gml:id="UUID_a761b717-45e6-478d-8544-5b8ec61c0a8f">
              <gml:surfaceMember>
                <gml:Polygon gml:id="GUID_1543405942858_111012029_2_0">
                  <gml:exterior>
                    <gml:LinearRing gml:id="GUID_1543405942858_111012029_2_0_0_">
                      <gml:posList srsDimension="3">329300.295 5730991.74 21.0 329296.88 5730986.581 21.0 329295.934 5730987.176 21.0 329295.837 5730987.027 21.0 329292.3 5730989.355 21.0 329292.365 5730989.464 21.0 329287.836 5730992.438 21.0 329287.518 5730992.643 21.0 329290.917 5730997.787 21.0 329294.315 5731002.931 21.0 329299.118 5730999.783 21.0 329299.191 5730999.861 21.0 329303.709 5730996.899 21.0 329300.295 5730991.74 21.0</gml:posList>
                    </gml:LinearRing>
                  </gml:exterior>
                </gml:Polygon>
              </gml:surfaceMember>
            </gml:MultiSurface>
          </bldg:lod2MultiSurface>
        </bldg:GroundSurface>
      </bldg:boundedBy>
      <bldg:address>
        <core:Address gml:id="UUID_7814f534-d84b-477d-8467-76d0f5bb0edd">
          <core:xalAddress>
            <xAL:AddressDetails>
              <xAL:Country>
                <xAL:CountryName>Germany</xAL:CountryName>
                <xAL:Locality Type="Town">
                  <xAL:LocalityName>Wesel</xAL:LocalityName>
                  <xAL:Thoroughfare Type="Street">
                    <xAL:ThoroughfareNumber>19</xAL:ThoroughfareNumber>
                    <xAL:ThoroughfareName>Böckersche Straße</xAL:ThoroughfareName>
                  </xAL:Thoroughfare>
                </xAL:Locality>
              </xAL:Country>
            </xAL:AddressDetails>
          </core:xalAddress>
        </core:Address>
      </bldg:address>
    </bldg:Building>
  </core:cityObjectMember>
</core:CityModel>