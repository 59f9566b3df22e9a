namespace OperatorPanel.Cli.Tests;

/// <summary>
/// The tests that run opanel against a simulated PLC over a socat pty in real time. Their time-outs are a few hundred
/// milliseconds; beside the other classes on a 2-core machine a thread can stall past them, so they run alone, after
/// the rest.
/// </summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class RealTimeSerialCollection
{
    public const string Name = "real-time serial";
}
