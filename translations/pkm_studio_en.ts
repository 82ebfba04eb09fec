<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>core</name>
    <message numerus="yes">
        <source>%n moving link(s)</source>
        <translation>
            <numerusform>%n moving link</numerusform>
            <numerusform>%n moving links</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pair(s)</source>
        <translation>
            <numerusform>%n pair</numerusform>
            <numerusform>%n pairs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n loop(s)</source>
        <translation>
            <numerusform>%n loop</numerusform>
            <numerusform>%n loops</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Chebyshev&apos;s W = %1 is wrong: %n planar loop equation(s) is/are redundant (an overconstrained planar chain)</source>
        <translation>
            <numerusform>Chebyshev&apos;s W = %1 is wrong: %n planar loop equation is redundant (an overconstrained planar chain)</numerusform>
            <numerusform>Chebyshev&apos;s W = %1 is wrong: %n planar loop equations are redundant (an overconstrained planar chain)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Somov–Malyshev&apos;s W = %1 is wrong: it counts 6 equations per loop and %n is/are redundant %2</source>
        <translation>
            <numerusform>Somov–Malyshev&apos;s W = %1 is wrong: it counts 6 equations per loop and %n is redundant %2</numerusform>
            <numerusform>Somov–Malyshev&apos;s W = %1 is wrong: it counts 6 equations per loop and %n are redundant %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n freedom(s)</source>
        <translation>
            <numerusform>%n freedom</numerusform>
            <numerusform>%n freedoms</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) leave(s) %1 uncontrolled (under-actuated)</source>
        <translation>
            <numerusform>%n actuated freedom leaves %1 uncontrolled (under-actuated)</numerusform>
            <numerusform>%n actuated freedoms leave %1 uncontrolled (under-actuated)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s) for mobility %1: redundantly actuated</source>
        <translation>
            <numerusform>%n actuated freedom for mobility %1: redundantly actuated</numerusform>
            <numerusform>%n actuated freedoms for mobility %1: redundantly actuated</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s): fully actuated</source>
        <translation>
            <numerusform>%n actuated freedom: fully actuated</numerusform>
            <numerusform>%n actuated freedoms: fully actuated</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n idle freedom(s) is/are included</source>
        <translation>
            <numerusform>%n idle freedom is included</numerusform>
            <numerusform>%n idle freedoms are included</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::AnimationDialog</name>
    <message numerus="yes">
        <source>Drawing %n frame(s)…</source>
        <translation>
            <numerusform>Drawing %n frame…</numerusform>
            <numerusform>Drawing %n frames…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Encoding %n frame(s)…</source>
        <translation>
            <numerusform>Encoding %n frame…</numerusform>
            <numerusform>Encoding %n frames…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>pkm::MobilityPanel</name>
    <message numerus="yes">
        <source>W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and %n of them are redundant.</source>
        <translation>
            <numerusform>W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and %n of them are redundant.</numerusform>
            <numerusform>W = %1, but the rank gives M = %2: the formula counts %3 equations per loop, and %n of them are redundant.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Links&lt;/b&gt;: %1 and %n moving link(s), n = %n: %2.</source>
        <translation>
            <numerusform>&lt;b&gt;Links&lt;/b&gt;: %1 and %n moving link, n = %n: %2.</numerusform>
            <numerusform>&lt;b&gt;Links&lt;/b&gt;: %1 and %n moving links, n = %n: %2.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Loops&lt;/b&gt;: %n independent loop(s), L = %n.</source>
        <translation>
            <numerusform>&lt;b&gt;Loops&lt;/b&gt;: %n independent loop, L = %n.</numerusform>
            <numerusform>&lt;b&gt;Loops&lt;/b&gt;: %n independent loops, L = %n.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Idle freedoms&lt;/b&gt;: %n (a part spinning about its own axis), counted in every number below.</source>
        <translation>
            <numerusform>&lt;b&gt;Idle freedoms&lt;/b&gt;: %n (a part spinning about its own axis), counted in every number below.</numerusform>
            <numerusform>&lt;b&gt;Idle freedoms&lt;/b&gt;: %n (a part spinning about its own axis), counted in every number below.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n redundant loop equation(s): %1</source>
        <translation>
            <numerusform>%n redundant loop equation: %1</numerusform>
            <numerusform>%n redundant loop equations: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>An open chain, no loop: nothing holds the %n freedom(s) of its pairs, M = F = %n.</source>
        <translation>
            <numerusform>An open chain, no loop: nothing holds the %n freedom of its pairs, M = F = %n.</numerusform>
            <numerusform>An open chain, no loop: nothing holds the %n freedoms of its pairs, M = F = %n.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n actuated freedom(s)</source>
        <translation>
            <numerusform>%n actuated freedom</numerusform>
            <numerusform>%n actuated freedoms</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 for mobility %2; with the actuators locked, it keeps %n freedom(s).</source>
        <translation>
            <numerusform>%1 for mobility %2; with the actuators locked, it keeps %n freedom.</numerusform>
            <numerusform>%1 for mobility %2; with the actuators locked, it keeps %n freedoms.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n revolute</source>
        <translation>
            <numerusform>%n revolute</numerusform>
            <numerusform>%n revolute</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n prismatic</source>
        <translation>
            <numerusform>%n prismatic</numerusform>
            <numerusform>%n prismatic</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n screw</source>
        <translation>
            <numerusform>%n screw</numerusform>
            <numerusform>%n screw</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n cylindrical</source>
        <translation>
            <numerusform>%n cylindrical</numerusform>
            <numerusform>%n cylindrical</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n planar cam</source>
        <translation>
            <numerusform>%n planar cam</numerusform>
            <numerusform>%n planar cam</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spherical</source>
        <translation>
            <numerusform>%n spherical</numerusform>
            <numerusform>%n spherical</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>At this pose the mechanism gains %n instantaneous freedoms (singularity).</source>
        <translation>
            <numerusform>At this pose the mechanism gains %n instantaneous freedom (singularity).</numerusform>
            <numerusform>At this pose the mechanism gains %n instantaneous freedoms (singularity).</numerusform>
        </translation>
    </message>
</context>
</TS>
