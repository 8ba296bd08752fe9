"""Node interfaces read from a workspace's own sources, without building them.

For each executable or component a package builds, which publishers, subscriptions,
services, clients, action servers and clients its code creates, with the names as
written (or the parameter they come from). This is the per-node half of the computation
graph; composing it with the launch graph (namespaces, remaps) comes later.
"""
