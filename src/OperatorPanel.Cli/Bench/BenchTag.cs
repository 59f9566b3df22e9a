using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Cli.Bench;

/// <summary>One watched address of a bench line and the group it is listed under ("inputs", "recipe", "alarms"…).</summary>
internal readonly record struct BenchTag(string Group, PlcAddress Address);
