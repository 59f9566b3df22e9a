using System.Globalization;
using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>The link step's "test connection": one IDENTIFY, its answer decoded and compared with step 1's CPU.</summary>
public sealed partial class LinkStepViewModel
{
    /// <summary>What the test found, for the operator; null before the first test.</summary>
    [ObservableProperty]
    public partial string? TestResult { get; private set; }

    /// <summary>True when the station answered and matches the chosen CPU; false on a failure or mismatch; null while untested or running.</summary>
    [ObservableProperty]
    public partial bool? TestSucceeded { get; private set; }

    /// <summary>
    /// TestConnectionCommand (TestConnectionCancelCommand stops it): one IDENTIFY through the tester, given up after the
    /// longest the link itself would take (<see cref="LinkConnectionTester.LongestTest"/>), so a port that hangs (a USB
    /// adapter's driver, a device that never answers) ends the test by itself and the wizard goes on.
    /// </summary>
    [RelayCommand(IncludeCancelCommand = true)]
    private async Task TestConnectionAsync(CancellationToken cancellationToken)
    {
        var cpu = _cpuStep.Cpu;
        if (_cpuStep.Station is not { } station || Problems.Length > 0 || string.IsNullOrWhiteSpace(PortName))
        {
            TestSucceeded = false;
            TestResult = "Fix the station address (step 1) and the link settings before testing.";
            return;
        }

        var link = Build();
        var where = string.Create(CultureInfo.InvariantCulture, $"Station {station.Address} on {link.PortName} at {link.LineText}");
        var longest = LinkConnectionTester.LongestTest(link, station);
        TestSucceeded = null;
        TestResult = string.Create(CultureInfo.InvariantCulture, $"{where}: asking... (at most {Math.Ceiling(longest.TotalSeconds):0} s)");
        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        try
        {
            if (link.Protocol == LinkProtocol.Ppi)
            {
                (TestSucceeded, TestResult) = Describe(where, await _tester.IdentifyPpiAsync(link, station, stop.Token).WaitAsync(longest, _time, stop.Token), cpu);
                return;
            }

            var reply = await _tester.IdentifyAsync(link, station, stop.Token).WaitAsync(longest, _time, stop.Token);
            (TestSucceeded, TestResult) = reply.Response switch
            {
                null => (false, Describe(where, link.PortName, reply.Failure!)),
                IdentifyResponse identity => Describe(where, identity, cpu),
                ErrorResponse refusal => (false, $"{where} refused IDENTIFY ({refusal.Error}): the handler is too old or not ours; regenerate it."),
                var other => (false, $"{where} answered IDENTIFY with a {other.Command} reply; is another device on the bus?"),
            };
        }
        catch (TimeoutException)
        {
            // The tester is told to stop; whatever it still holds (a port stuck in its driver) is left to finish alone.
            await stop.CancelAsync();
            TestSucceeded = false;
            TestResult = string.Create(CultureInfo.InvariantCulture,
                $"{where}: nothing came back within {Math.Ceiling(longest.TotalSeconds):0} s, longer than the link itself waits: the port may be held by another program or its driver may hang. Check the port, unplug and replug a USB adapter, then test again.");
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            TestSucceeded = null;
            TestResult = $"{where}: test cancelled.";
        }
    }

    private static string Describe(string where, string portName, PlcCommunicationException failure) => failure.Kind switch
    {
        PlcErrorKind.PortUnavailable => $"{portName} could not be used: {failure.Message}",
        PlcErrorKind.HandlerOutdated => $"{where}: {failure.Message}.",
        PlcErrorKind.AnotherMaster => $"{where}: another PPI master is on the bus; the panel does not share it. ({failure.Message})",
        PlcErrorKind.FrameCorrupt => $"{where}: garbled replies; check that baud rate and parity match the handler. ({failure.Message})",
        PlcErrorKind.Timeout or PlcErrorKind.NegativeReply or PlcErrorKind.NoAnswer =>
            $"{where}: no answer. Check the cable or radio module, the station address, that the PLC is in RUN with its "
            + $"mode switch at RUN (not TERM) and that the handler is loaded. ({failure.Message})",
    };

    /// <summary>Over PPI: SMB6 against the chosen CPU (by code: 224 and 224XP share it); RUN or STOP cannot be known.</summary>
    private static (bool, string) Describe(string where, PpiIdentifyOutcome outcome, Core.Cpu.CpuProfile cpu)
    {
        if (outcome.Identity is not { } identity)
        {
            return (false, $"{where} over PPI: {outcome.Error}. Check the cable, the station's PPI address and baud rate (its system block), "
                + "and that no other master (Micro/WIN, a TD 200) is on the bus.");
        }

        var answer = string.Create(CultureInfo.InvariantCulture,
            $"{where} answered over PPI (no handler needed): SMB6 16#{identity.Smb6:X2}, mode switch {(identity.SwitchAtRun ? "RUN" : "TERM")}, "
            + $"last scan {identity.LastScanMs} ms; RUN or STOP is not known over PPI.");
        return (identity.Smb6 & 0xF0) == cpu.CpuIdCode
            ? (true, $"{answer} Matches {cpu.DisplayName}.")
            : (false, string.Create(CultureInfo.InvariantCulture, $"{answer} CPU mismatch: {cpu.DisplayName} has SMB6 16#{cpu.CpuIdCode:X2}."));
    }

    private static (bool, string) Describe(string where, IdentifyResponse identity, Core.Cpu.CpuProfile cpu)
    {
        var answer = string.Create(CultureInfo.InvariantCulture,
            $"{where} answered: handler for {IdentifyCheck.DescribeGeneratedFor(identity)}, protocol {identity.ProtocolVersion}, "
            + $"handler revision {identity.HandlerRevision}, mode switch {(identity.ModeSwitchRun ? "RUN" : "TERM")}, last scan {identity.LastScanMs} ms.");
        return IdentifyCheck.Mismatch(identity, cpu) is { } mismatch
            ? (false, $"{answer} CPU mismatch with {cpu.DisplayName}: {mismatch}.")
            : (true, $"{answer} Matches {cpu.DisplayName}.");
    }
}
