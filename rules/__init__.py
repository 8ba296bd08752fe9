"""Built-in rules, one module each; ``BUILTIN`` is the explicit, sorted table."""

from __future__ import annotations

from launchverify.rule import Rule
from launchverify.rules.arguments.invalid_default import InvalidDefault
from launchverify.rules.arguments.missing_required_argument import MissingRequiredArgument
from launchverify.rules.arguments.undeclared_argument import UndeclaredArgument
from launchverify.rules.arguments.unknown_include_argument import UnknownIncludeArgument
from launchverify.rules.arguments.unused_argument import UnusedArgument
from launchverify.rules.conditions.constant_condition import ConstantCondition
from launchverify.rules.conditions.invalid_condition_value import InvalidConditionValue
from launchverify.rules.conditions.unreachable_condition import UnreachableCondition
from launchverify.rules.events.dangling_event_target import DanglingEventTarget
from launchverify.rules.events.event_cycle import EventCycle
from launchverify.rules.files.duplicate_package import DuplicatePackage
from launchverify.rules.files.include_cycle import IncludeCycle
from launchverify.rules.files.missing_file import MissingFile
from launchverify.rules.files.unknown_executable import UnknownExecutable
from launchverify.rules.files.unknown_package import UnknownPackage
from launchverify.rules.health.evaluation_error import EvaluationError
from launchverify.rules.health.internal_error import InternalError
from launchverify.rules.health.parse_error import ParseError
from launchverify.rules.health.unmodeled_construct import UnmodeledConstruct
from launchverify.rules.health.unused_suppression import UnusedSuppression
from launchverify.rules.lifecycle.invalid_lifecycle_transition import (
    InvalidLifecycleTransition,
)
from launchverify.rules.lifecycle.lifecycle_deadlock import LifecycleDeadlock
from launchverify.rules.lifecycle.manager_unknown_node import ManagerUnknownNode
from launchverify.rules.lifecycle.unknown_container import UnknownContainer
from launchverify.rules.lifecycle.unknown_controller import UnknownController
from launchverify.rules.lifecycle.unknown_controller_type import UnknownControllerType
from launchverify.rules.lifecycle.unknown_lifecycle_label import UnknownLifecycleLabel
from launchverify.rules.naming.duplicate_node_name import DuplicateNodeName
from launchverify.rules.naming.invalid_domain_id import InvalidDomainId
from launchverify.rules.naming.invalid_name import InvalidName
from launchverify.rules.naming.remap_collision import RemapCollision
from launchverify.rules.parameters.inconsistent_sim_time import InconsistentSimTime
from launchverify.rules.parameters.missing_required_parameter import MissingRequiredParameter
from launchverify.rules.parameters.param_file_error import ParamFileError
from launchverify.rules.parameters.param_type_conflict import ParamTypeConflict
from launchverify.rules.parameters.parameter_out_of_range import ParameterOutOfRange
from launchverify.rules.parameters.parameter_type_mismatch import ParameterTypeMismatch
from launchverify.rules.parameters.unknown_parameter import UnknownParameter
from launchverify.rules.parameters.unmatched_param_block import UnmatchedParamBlock
from launchverify.rules.wiring.competing_publishers import CompetingPublishers
from launchverify.rules.wiring.incompatible_qos import IncompatibleQos
from launchverify.rules.wiring.missing_peer import MissingPeer
from launchverify.rules.wiring.type_mismatch import TypeMismatch
from launchverify.rules.wiring.unused_remap import UnusedRemap

BUILTIN: tuple[type[Rule], ...] = (
    ParseError,               # LV001
    EvaluationError,          # LV002
    UnmodeledConstruct,       # LV003
    UnusedSuppression,        # LV004
    InternalError,            # LV005
    DuplicateNodeName,        # LV101
    InvalidName,              # LV102
    RemapCollision,           # LV103
    InvalidDomainId,          # LV104
    UndeclaredArgument,       # LV201
    UnusedArgument,           # LV202
    InvalidDefault,           # LV203
    UnknownIncludeArgument,   # LV204
    UnreachableCondition,     # LV205
    ConstantCondition,        # LV206
    InvalidConditionValue,    # LV207
    MissingRequiredArgument,  # LV208
    IncludeCycle,             # LV301
    MissingFile,              # LV302
    UnknownPackage,           # LV303
    UnknownExecutable,        # LV304
    DuplicatePackage,         # LV305
    ParamFileError,           # LV401
    UnmatchedParamBlock,      # LV402
    ParamTypeConflict,        # LV403
    InconsistentSimTime,      # LV404
    UnknownParameter,         # LV405
    ParameterTypeMismatch,    # LV406
    ParameterOutOfRange,      # LV407
    MissingRequiredParameter,  # LV408
    EventCycle,               # LV501
    DanglingEventTarget,      # LV502
    LifecycleDeadlock,        # LV503
    InvalidLifecycleTransition,  # LV504
    ManagerUnknownNode,       # LV505
    UnknownContainer,         # LV506
    UnknownController,        # LV507
    UnknownLifecycleLabel,    # LV508
    UnknownControllerType,    # LV509
    UnusedRemap,              # LV601
    MissingPeer,              # LV602
    TypeMismatch,             # LV603
    CompetingPublishers,      # LV604
    IncompatibleQos,          # LV605
)
