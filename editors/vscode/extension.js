// The RobotBASIC extension: starts `rb lsp` as the language server for .bas files and adds
// "Run this file with rb" (the server offers it as a code lens above each program).
const vscode = require('vscode');
const { LanguageClient, TransportKind } = require('vscode-languageclient/node');

let client;

function startClient() {
  const config = vscode.workspace.getConfiguration('rb');
  const command = config.get('path', 'rb');
  // TransportKind.stdio: the client adds --stdio, which rb lsp accepts.
  const serverOptions = { command, args: ['lsp'], transport: TransportKind.stdio };
  const clientOptions = {
    documentSelector: [
      { scheme: 'file', language: 'robotbasic' },
      { scheme: 'untitled', language: 'robotbasic' },
    ],
    // rb.portable: rb check --portable's warnings too; a change of the "rb" settings is sent
    // to the server (workspace/didChangeConfiguration), which checks the open programs again.
    initializationOptions: { portable: config.get('portable', false) },
    synchronize: {
      configurationSection: 'rb',
      fileEvents: vscode.workspace.createFileSystemWatcher('**/*.bas'),
    },
  };
  client = new LanguageClient('rb', 'rb', serverOptions, clientOptions);
  return client.start();
}

function runFile(uriText) {
  const uri = uriText ? vscode.Uri.parse(uriText) : vscode.window.activeTextEditor?.document.uri;
  if (!uri || uri.scheme !== 'file') {
    vscode.window.showWarningMessage('rb: save the program to a file first.');
    return;
  }
  const config = vscode.workspace.getConfiguration('rb');
  const rb = config.get('path', 'rb');
  const args = config.get('runArguments', ['run', '--tui']);
  const quote = (s) => "'" + s.replace(/'/g, "'\\''") + "'";
  const doc = vscode.workspace.textDocuments.find((d) => d.uri.toString() === uri.toString());
  const save = doc && doc.isDirty ? doc.save() : Promise.resolve(true);
  save.then(() => {
    const terminal = vscode.window.createTerminal({ name: 'rb run' });
    terminal.show();
    terminal.sendText([quote(rb), ...args.map(quote), quote(uri.fsPath)].join(' '));
  });
}

function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand('rb.runFile', runFile),
    vscode.commands.registerCommand('rb.restartServer', async () => {
      if (client) await client.stop();
      await startClient();
    }),
  );
  return startClient();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
