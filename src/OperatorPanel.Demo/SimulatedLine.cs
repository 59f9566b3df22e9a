using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using Serilog;

namespace OperatorPanel.Demo;

/// <summary>
/// A line from <see cref="SimulatedLineFactory"/> (the STL model runs the handler StlGen generates,
/// <see cref="GeneratedHandler"/>), with what <c>opanel simulate</c> and the demo line do with it.
/// </summary>
public sealed class SimulatedLine
{
    private SimulatedLine(ISimulatedLine line, bool runsProcess)
    {
        Line = line;
        RunsProcess = runsProcess;
    }

    public ISimulatedLine Line { get; }

    public bool RunsProcess { get; }

    /// <summary>
    /// The stations on a line of <paramref name="serial"/>'s baud, parity and data bits; false with a message naming the
    /// station and the generator's or loader's diagnostic when the STL model cannot run one.
    /// </summary>
    public static bool TryCreate(
        IEnumerable<HandlerConfig> stations, SimulationModel model, SerialSettings serial, bool runProcess,
        [NotNullWhen(true)] out SimulatedLine? line, [NotNullWhen(false)] out string? error) =>
        TryCreate(stations, model, serial, runProcess, PpiMode.BesideHandler, out line, out error);

    /// <summary>As above; <paramref name="ppi"/> = <see cref="PpiMode.WithoutHandler"/> loads no handler (simulate --ppi).</summary>
    public static bool TryCreate(
        IEnumerable<HandlerConfig> stations, SimulationModel model, SerialSettings serial, bool runProcess, PpiMode ppi,
        [NotNullWhen(true)] out SimulatedLine? line, [NotNullWhen(false)] out string? error)
    {
        if (!SimulatedLineFactory.TryCreate(stations, model, serial, runProcess, GeneratedHandler, ppi, out var created, out error))
        {
            line = null;
            return false;
        }

        line = new SimulatedLine(created, runProcess);
        return true;
    }

    /// <summary>Runs the line ahead by <paramref name="time"/> so the first reply already shows a running line.</summary>
    public void WarmUp(TimeSpan time) => Line.RunUntil(Line.Now + time);

    public SimulatedPlcHost HostOn(ITransport port, TimeProvider time, ILogger log) => new(port, Line, time, log);

    /// <summary>
    /// The simulated station for a handler generated with <paramref name="options"/> (opanel simulate): every option
    /// the generator takes that the station needs, so <see cref="GeneratedHandler"/> generates the same handler again
    /// (the line settings come from the line). The options must have passed the generator's check.
    /// </summary>
    public static HandlerConfig ConfigFor(HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        var v3 = options.Protocol == 3;
        return new HandlerConfig(
            new Core.Addressing.Station(options.Station), options.Cpu, options.Port, (byte)options.WriteMask, (byte)options.ReplyDelayMs,
            v3 ? null : options.EffectiveBufferStart, options.AllowStop, options.CopyBytes, options.CharTimeoutMs, options.FirstSubroutine, options.FirstInterrupt)
        {
            Protocol = options.Protocol,
            Compact = options.Compact,
            V3First = v3 ? options.BufferStart : null,
        };
    }

    /// <summary>The handler StlGen generates for the station: the same text Generate PLC code / opanel generate saves.</summary>
    private static bool GeneratedHandler(HandlerConfig config, SerialSettings serial, [NotNullWhen(true)] out string? awlText, [NotNullWhen(false)] out string? error) =>
        HandlerGenerator.TryGenerateAwl(
            HandlerOptions.ForLine(config.Cpu, config.Port, config.Station.Address, config.WriteMask, config.ReplyDelayMs, serial) with
            {
                Protocol = config.Protocol,
                Compact = config.Compact,
                AllowStop = config.AllowStop,
                BufferStart = config.Protocol == 3 ? config.V3First : config.BufferStart,
                CopyBytes = config.CopyBytes,
                CharTimeoutMs = config.CharTimeoutMs,
                FirstSubroutine = config.FirstSubroutine,
                FirstInterrupt = config.FirstInterrupt,
            },
            out awlText,
            out error);
}
